"""The BenchPilot GUI started offscreen on its simulators for the client's tests, with
its API socket, settings and data in a temporary folder of its own."""
import os
import subprocess
import tempfile
import time

import benchpilot


def gui_binary():
    bin_dir = os.environ.get("BP_BIN_DIR")
    if not bin_dir:
        here = os.path.dirname(os.path.abspath(__file__))
        bin_dir = os.path.join(here, "..", "..", "..", "build", "app")
    return os.path.join(bin_dir, "benchpilot")


class Gui:
    """benchpilot --api-socket TMP/api.sock, both simulated instruments connected."""

    def __init__(self, ready_timeout_s=60):
        self.dir = tempfile.TemporaryDirectory(prefix="bp-api-")
        self.socket = os.path.join(self.dir.name, "run", "api.sock")
        env = dict(os.environ)
        env.update({
            "QT_QPA_PLATFORM": "offscreen",
            "XDG_CONFIG_HOME": os.path.join(self.dir.name, "config"),
            "XDG_DATA_HOME": os.path.join(self.dir.name, "data"),
            "XDG_RUNTIME_DIR": os.path.join(self.dir.name, "runtime"),
            "HOME": self.dir.name,
        })
        os.makedirs(env["XDG_RUNTIME_DIR"], mode=0o700, exist_ok=True)
        self.log = open(os.path.join(self.dir.name, "gui.log"), "w")
        self.process = subprocess.Popen([gui_binary(), "--api-socket", self.socket], env=env,
                                        stdout=self.log, stderr=subprocess.STDOUT)
        deadline = time.monotonic() + ready_timeout_s
        while True:
            if self.process.poll() is not None:
                raise RuntimeError("benchpilot exited with %s (see %s)" % (self.process.returncode, self.log.name))
            try:
                with benchpilot.connect(self.socket, name="readiness probe") as c:
                    links = {i["instrument"]: i["link"] for i in c.hello["instruments"]}
                    if all(v == "ready" for v in links.values()):
                        break
            except benchpilot.ConnectionLost:
                pass
            if time.monotonic() > deadline:
                self.stop()
                raise RuntimeError("benchpilot did not become ready within %s s" % ready_timeout_s)
            time.sleep(0.2)

    def connect(self, name):
        return benchpilot.connect(self.socket, name=name)

    def stop(self):
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=20)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self.log.close()
        self.dir.cleanup()
