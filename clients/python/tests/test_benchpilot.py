"""The Python client against the GUI offscreen on its simulators (docs/api.md).

A script and the operator share one simulated stage: the script acquires, homes and
jogs; a script killed with SIGKILL in the middle of a continuous jog leaves the axis at
rest within 500 ms of the simulator's clock; an E-stop from a second client latches at
once while the first holds the lease. (The operator's Take back is tested in-process,
tests/gui/api_take_back_test.cpp: it needs the window's button.)

Run: PYTHONPATH=clients/python BP_BIN_DIR=build/app python3 -m unittest discover -s clients/python/tests
"""
import os
import queue
import signal
import subprocess
import sys
import textwrap
import time
import unittest

import benchpilot
from gui_process import Gui

HERE = os.path.dirname(os.path.abspath(__file__))
CLIENT_DIR = os.path.dirname(HERE)


def wait_until(condition, timeout_s=30, every_s=0.05):
    """Polls `condition` until it is true; a generous bound for a loaded machine, never a measurement."""
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        value = condition()
        if value:
            return value
        time.sleep(every_s)
    return condition()


class ScriptOnTheBench(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.gui = Gui()

    @classmethod
    def tearDownClass(cls):
        cls.gui.stop()

    def tearDown(self):
        # Leave the stage as the next test expects it: no E-stop, nothing moving.
        with self.gui.connect("cleanup") as c:
            if c.call("device.status", instrument="stage")["estop"]:
                with c.acquire():
                    c.call("device.reset", instrument="stage")
            c.call("device.stop", instrument="stage")

    def test_reading_needs_no_lease_and_errors_carry_the_servers_code_and_message(self):
        with self.gui.connect("reader") as bp:
            status = bp.device.status(instrument="stage")
            self.assertEqual(status["instrument"], "stage")
            self.assertEqual(set(status["axes"]), {"X", "Y"})
            methods = {m["name"] for m in bp.call("rpc.discover")["methods"]}
            self.assertIn("device.move", methods)
            with self.assertRaises(benchpilot.InvalidParams) as e:
                bp.device.move(instrument="stage", targets={"X": "far"})
            self.assertEqual(e.exception.code, -32602)
            self.assertEqual(e.exception.data["field"], "targets.X")
            with self.assertRaises(benchpilot.MethodNotFound):
                bp.call("device.teleport")
            with self.assertRaises(benchpilot.NotInControl) as e:
                bp.device.jog(instrument="stage", axis="X", velocity=1)
            self.assertIn("control.acquire", e.exception.message)

    def test_a_script_acquires_homes_and_jogs_and_its_heartbeat_keeps_control(self):
        with self.gui.connect("homer") as bp, bp.acquire() as lease:
            homed = bp.device.home(instrument="stage", axes="X")
            self.assertTrue(homed["axes"]["X"]["homed"])
            start = homed["axes"]["X"]["measured"]
            bp.device.jog(instrument="stage", axis="X", velocity=2)  # held until stop or loss of control
            time.sleep(1.0)  # twice the heartbeat timeout: the lease's thread keeps it
            self.assertFalse(lease.lost.is_set())
            stopped = bp.device.stop(instrument="stage")
            self.assertFalse(stopped["axes"]["X"]["moving"])
            self.assertGreater(stopped["axes"]["X"]["measured"], start + 0.5)
            journal = bp.subscribe({"log": {}})
            entries = journal.get(timeout=10)["data"]["entries"]
            journal.close()
        self.assertTrue(any(e.get("client", "").startswith("homer") and "device.jog" in e["text"] for e in entries),
                        "every changing call is in the event log with the client's name")

    def test_a_script_killed_mid_jog_leaves_the_axis_at_rest_within_500_ms_of_device_time(self):
        child = subprocess.Popen([sys.executable, "-c", textwrap.dedent("""
            import sys, time, benchpilot
            bp = benchpilot.connect(sys.argv[1], name="doomed jogger")
            bp.acquire()
            bp.device.jog(instrument="stage", axis="X", velocity=2)
            print("jogging", flush=True)
            time.sleep(120)
            """), self.gui.socket], stdout=subprocess.PIPE, env=dict(os.environ, PYTHONPATH=CLIENT_DIR))
        try:
            with self.gui.connect("watcher") as bp:
                live = bp.subscribe({"positions": {"instrument": "stage", "max_hz": 50},
                                     "state": {"instrument": "stage", "max_hz": 50}})
                self.assertEqual(child.stdout.readline().strip(), b"jogging")
                state = {}
                last_moving_us = None
                # Until the stage is seen moving, and a little after (the newest positions).
                while last_moving_us is None or not state.get("moving", {}).get("X"):
                    msg = live.get(timeout=30)
                    if msg["topic"] == "state":
                        state.update(msg["data"])
                    elif msg["topic"] == "positions" and state.get("moving", {}).get("X"):
                        last_moving_us = msg["device_time_us"]
                while True:  # the newest reading before the kill: the kill is later than this
                    try:
                        msg = live.get(timeout=0.05)
                    except queue.Empty:
                        break
                    if msg["topic"] == "positions":
                        last_moving_us = msg["device_time_us"]
                child.send_signal(signal.SIGKILL)
                child.wait(timeout=10)
                rest_us = None
                while rest_us is None:
                    msg = live.get(timeout=30)
                    if msg["topic"] == "state":
                        state.update(msg["data"])
                        if not state["moving"]["X"]:
                            rest_us = msg["device_time_us"]
                live.close()
            sys.stderr.write("\n  at rest %.0f ms of device time after the last reading before SIGKILL\n"
                             % ((rest_us - last_moving_us) / 1000))
            self.assertLessEqual(rest_us - last_moving_us, 500_000,
                                 "device time from the last reading before the kill to rest")
        finally:
            if child.poll() is None:
                child.kill()
                child.wait()
            child.stdout.close()

    def test_an_estop_from_a_second_client_latches_at_once_while_the_first_holds_the_lease(self):
        with self.gui.connect("holder") as holder, self.gui.connect("bystander") as other:
            with holder.acquire():
                holder.device.jog(instrument="stage", axis="Y", velocity=1)
                result = other.device.estop(instrument="stage")  # no lease: E-stop is never gated
                self.assertTrue(result["estop"])
                with self.assertRaises(benchpilot.EStopLatched):
                    holder.device.jog(instrument="stage", axis="Y", velocity=1, seconds=0.2)
                with self.assertRaises(benchpilot.NotInControl):
                    other.device.reset(instrument="stage")  # clearing it is a change: the holder's
                self.assertFalse(holder.device.reset(instrument="stage")["estop"])

    def test_subscribe_gives_a_snapshot_then_only_changes_with_sequence_numbers(self):
        with self.gui.connect("listener") as bp, self.gui.connect("mover") as mover:
            sub = bp.subscribe({"positions": {"instrument": "stage", "max_hz": 20}})
            first = sub.get(timeout=10)
            self.assertTrue(first["snapshot"])
            self.assertEqual(set(first["data"]), {"X", "Y"})
            self.assertIn("following_error", first["data"]["X"])
            with mover.acquire():
                mover.device.jog(instrument="stage", axis="X", velocity=1, seconds=0.6)
            seq = first["seq"]
            changes = 0
            while changes < 3:
                msg = sub.get(timeout=10)
                self.assertFalse(msg["snapshot"])
                self.assertGreater(msg["seq"], seq)
                self.assertEqual(msg["coalesced"], msg["seq"] - seq - 1, "the sequence gap is what was folded")
                self.assertNotIn("Y", msg["data"], "Y did not move: only what changed")
                seq = msg["seq"]
                changes += 1
            sub.close()

    def test_the_sweep_example_reads_the_grating_at_each_point(self):
        out = subprocess.run([sys.executable, os.path.join(CLIENT_DIR, "examples", "position_sweep.py"),
                              "--socket", self.gui.socket, "--points", "3", "--step", "0.2", "--settle-s", "0.1"],
                             capture_output=True, text=True, timeout=120)
        self.assertEqual(out.returncode, 0, out.stderr)
        lines = out.stdout.strip().splitlines()
        self.assertEqual(lines[0], "point,commanded_mm,measured_mm,following_error_um")
        self.assertEqual(len(lines), 4)
        commanded = [float(l.split(",")[1]) for l in lines[1:]]
        self.assertAlmostEqual(commanded[2] - commanded[0], 0.4, places=3)


if __name__ == "__main__":
    unittest.main()
