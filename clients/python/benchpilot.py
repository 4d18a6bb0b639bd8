"""BenchPilot's scripting API from Python: the standard library only (docs/api.md).

The GUI serves JSON-RPC 2.0 on a Unix socket, one JSON object per line. Its methods
are benchpilot-cli's commands (``device.move`` is ``benchpilot-cli move``) and their
results are exactly the CLI's ``--json`` objects.

    import benchpilot

    with benchpilot.connect(name="sweep") as bp:
        print(bp.call("device.status", instrument="stage"))
        with bp.acquire() as lease:              # control, kept with a heartbeat thread
            bp.device.move(instrument="stage", targets={"X": 1}, relative=True)
        for msg in bp.subscribe({"positions": {"instrument": "stage", "max_hz": 20}}):
            print(msg["seq"], msg["data"])
            break

Errors come back as ApiError (or a subclass naming the case) with the server's
``code``, ``message`` and ``data``.
"""

import itertools
import json
import os
import queue
import socket
import sys
import threading

__all__ = [
    "ApiError", "InvalidParams", "MethodNotFound", "Refused", "NotHomed", "SoftLimit", "EStopLatched",
    "Busy", "LinkTrouble", "NotInControl", "Cancelled", "ConnectionLost",
    "Client", "Lease", "Subscription", "connect", "default_socket_path", "HEARTBEAT_S",
]

#: How often the lease's heartbeat thread beats; the server drops a lease after 500 ms of silence.
HEARTBEAT_S = 0.1


def default_socket_path():
    """Where the GUI listens unless told otherwise (benchpilot --api-socket).

    $XDG_RUNTIME_DIR/benchpilot/api.sock, or /tmp/benchpilot-UID/api.sock when
    XDG_RUNTIME_DIR is not set: the rule the GUI and benchpilot-cli --attach follow
    (cli::apiSocketPathFor in app/cli/attach.cpp), spelled the same way; a test runs
    both in the same environments and compares.
    """
    runtime = os.environ.get("XDG_RUNTIME_DIR")
    if runtime:
        return os.path.join(runtime, "benchpilot", "api.sock")
    return "/tmp/benchpilot-%d/api.sock" % os.getuid()


class ApiError(Exception):
    """An error the server answered: its JSON-RPC code, message and data."""

    def __init__(self, code, message, data=None):
        super().__init__("%s (%s)" % (message, code))
        self.code = code
        self.message = message
        self.data = data or {}


class InvalidParams(ApiError):
    """-32602 (and -32600, -32700): a parameter is wrong; data["field"] names it."""


class MethodNotFound(ApiError):
    """-32601."""


class Refused(ApiError):
    """-32001: the device refused, or the motion failed."""


class NotHomed(Refused):
    """-32002."""


class SoftLimit(Refused):
    """-32003."""


class EStopLatched(Refused):
    """-32004: reset the E-stop first (device.reset, with the lease)."""


class Busy(Refused):
    """-32005: the operator runs a job; control stays with the GUI until it ends."""


class LinkTrouble(ApiError):
    """-32010: no instrument, link lost, no answer."""


class NotInControl(ApiError):
    """-32020: the call needs the control lease (acquire it), or the operator took it back."""


class Cancelled(ApiError):
    """-32040: call.cancel (or the GUI closing) interrupted the call."""


class ConnectionLost(ApiError):
    """The connection to the GUI closed before the answer came."""

    def __init__(self, message="the connection to BenchPilot closed"):
        super().__init__(None, message)


_ERRORS = {
    -32700: InvalidParams, -32600: InvalidParams, -32602: InvalidParams, -32601: MethodNotFound,
    -32001: Refused, -32002: NotHomed, -32003: SoftLimit, -32004: EStopLatched, -32005: Busy,
    -32010: LinkTrouble, -32020: NotInControl, -32040: Cancelled,
}

# The API's own methods take no lease; every other method is a CLI command and may need it.
_OWN_PREFIXES = ("rpc.", "client.", "control.", "call.", "cli.")
_OWN_METHODS = ("subscribe", "unsubscribe")


def _error(e):
    code = e.get("code")
    return _ERRORS.get(code, ApiError)(code, e.get("message", ""), e.get("data"))


class _Pending:
    __slots__ = ("event", "answer", "progress")

    def __init__(self, progress):
        self.event = threading.Event()
        self.answer = None
        self.progress = progress


class Subscription:
    """Live messages of one subscription, as an iterator of their params: topic,
    instrument, seq, device_time_us, snapshot, coalesced, coalesced_total,
    dropped_total, data. The first message of each topic is a full snapshot; later
    ones carry only what changed."""

    #: Messages held for a reader that falls behind; the oldest go first (and are counted).
    MAX_BACKLOG = 10000

    def __init__(self, client, sid, topics):
        self._client = client
        self.id = sid
        self.topics = topics
        self._queue = queue.Queue()
        self.dropped_here = 0
        self._closed = False

    def _put(self, params):
        if self._queue.qsize() >= self.MAX_BACKLOG:
            try:
                self._queue.get_nowait()
                self.dropped_here += 1
            except queue.Empty:
                pass
        self._queue.put(params)

    def get(self, timeout=None):
        """The next message; raises queue.Empty after `timeout` seconds, ConnectionLost if closed."""
        item = self._queue.get(timeout=timeout)
        if item is None:
            raise ConnectionLost()
        return item

    def __iter__(self):
        return self

    def __next__(self):
        item = self._queue.get()
        if item is None:
            raise StopIteration
        return item

    def close(self):
        if not self._closed:
            self._closed = True
            try:
                self._client.call("unsubscribe", subscription=self.id)
            except (ApiError, OSError):
                pass
            self._queue.put(None)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


class Lease:
    """The control lease: one holder at a time; the operator can take it back (then the
    next call raises NotInControl and `lost` is set). A thread keeps it with heartbeats
    while it is held; `release()` (or leaving the ``with``) gives it back."""

    def __init__(self, client, token, since):
        self._client = client
        self.token = token
        self.since = since
        self.lost = threading.Event()
        self.lost_reason = None
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._beat, name="benchpilot-heartbeat", daemon=True)
        self._thread.start()

    def _beat(self):
        while not self._stop.wait(HEARTBEAT_S):
            if self.lost.is_set():
                return
            try:
                self._client.notify("control.heartbeat", lease=self.token)
            except (ApiError, OSError):
                return

    def release(self):
        self._stop.set()
        if self._client._lease is self:
            self._client._lease = None
        if not self.lost.is_set():
            try:
                self._client.call("control.release", lease=self.token)
            except (NotInControl, ConnectionLost):
                pass
        self.lost.set()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.release()


class _Namespace:
    def __init__(self, client, prefix):
        self._client = client
        self._prefix = prefix

    def __getattr__(self, name):
        method = "%s.%s" % (self._prefix, name)

        def call(params=None, **kwargs):
            return self._client.call(method, params, **kwargs)

        return call


class Client:
    """A connection to the running BenchPilot GUI."""

    def __init__(self, path=None, name=None, timeout=5.0):
        self.path = path or default_socket_path()
        self._sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        self._sock.settimeout(timeout)
        try:
            self._sock.connect(self.path)
        except OSError as e:
            self._sock.close()
            raise ConnectionLost("no BenchPilot GUI is listening at %s (%s): start benchpilot, "
                                 "or give its --api-socket path" % (self.path, e)) from None
        self._sock.settimeout(None)
        self._write_lock = threading.Lock()
        self._ids = itertools.count(1)
        self._pending = {}
        self._subscriptions = {}
        self._early = {}  # messages of a subscription whose answer has not been read yet
        self._sub_lock = threading.Lock()
        self._lease = None
        self._closed = threading.Event()
        self._reader = threading.Thread(target=self._read, name="benchpilot-reader", daemon=True)
        self._reader.start()
        self.hello = self.call("client.hello", name=name or os.path.basename(sys.argv[0] or "python"), cwd=os.getcwd())

    # ---- plumbing -------------------------------------------------------------------
    def _send(self, message):
        data = (json.dumps(message, separators=(",", ":")) + "\n").encode()
        try:
            with self._write_lock:
                self._sock.sendall(data)
        except OSError as e:
            raise ConnectionLost("the connection to BenchPilot closed (%s)" % e) from None

    def _read(self):
        buffer = b""
        try:
            while True:
                chunk = self._sock.recv(65536)
                if not chunk:
                    break
                buffer += chunk
                while b"\n" in buffer:
                    line, buffer = buffer.split(b"\n", 1)
                    if line.strip():
                        self._dispatch(json.loads(line))
        except (OSError, ValueError):
            pass
        finally:
            self._closed.set()
            for p in list(self._pending.values()):
                p.event.set()
            for s in list(self._subscriptions.values()):
                s._queue.put(None)
            if self._lease:
                self._lease.lost_reason = self._lease.lost_reason or "connection_closed"
                self._lease.lost.set()

    def _dispatch(self, m):
        method = m.get("method")
        if method is None:
            p = self._pending.pop(m.get("id"), None)
            if p:
                p.answer = m
                p.event.set()
            return
        params = m.get("params", {})
        if method == "subscription":
            with self._sub_lock:
                s = self._subscriptions.get(params.get("subscription"))
                if s:
                    s._put(params)
                else:
                    self._early.setdefault(params.get("subscription"), []).append(params)
        elif method == "control.lost":
            if self._lease:
                self._lease.lost_reason = params.get("reason")
                self._lease.lost.set()
        elif method == "call.progress":
            p = self._pending.get(params.get("call"))
            if p and p.progress:
                p.progress(params.get("data"))

    # ---- calls ----------------------------------------------------------------------
    def call(self, method, params=None, timeout=None, progress=None, **kwargs):
        """Calls `method` with `params` (a dict) and/or keyword arguments; returns the result.
        The lease, when held, goes with every command method. `progress` is called with each
        progress object of a job (a recipe's wells, a scan's tiles) before the result."""
        params = dict(params or {}, **kwargs)
        if self._lease and "lease" not in params and not method.startswith(_OWN_PREFIXES) and method not in _OWN_METHODS:
            params["lease"] = self._lease.token
        if self._closed.is_set():
            raise ConnectionLost()
        cid = next(self._ids)
        pending = _Pending(progress)
        self._pending[cid] = pending
        if self._closed.is_set():  # closed while registering: the reader will not answer it
            self._pending.pop(cid, None)
            raise ConnectionLost()
        try:
            self._send({"jsonrpc": "2.0", "id": cid, "method": method, "params": params})
        except ConnectionLost:
            self._pending.pop(cid, None)
            raise
        if not pending.event.wait(timeout):
            self._pending.pop(cid, None)
            raise TimeoutError("%s: no answer within %s s" % (method, timeout))
        if pending.answer is None:
            raise ConnectionLost()
        if "error" in pending.answer:
            raise _error(pending.answer["error"])
        return pending.answer.get("result")

    def notify(self, method, params=None, **kwargs):
        """Sends a notification (never answered)."""
        self._send({"jsonrpc": "2.0", "method": method, "params": dict(params or {}, **kwargs)})

    def __getattr__(self, name):
        # bp.device.move(...), bp.recipe.run(...), bp.tuning.step_test(...)
        if name.startswith("_"):
            raise AttributeError(name)
        return _Namespace(self, name)

    # ---- control and live data ------------------------------------------------------
    def acquire(self, name=None):
        """Takes the control lease (a Lease, usable with ``with``)."""
        params = {"client": name} if name else {}
        result = self.call("control.acquire", **params)
        self._lease = Lease(self, result["lease"], result.get("since"))
        return self._lease

    @property
    def lease(self):
        return self._lease

    def subscribe(self, topics):
        """Subscribes to topics ({"positions": {"instrument": "stage", "max_hz": 50}, "state": {}, …});
        returns a Subscription (an iterator of messages)."""
        result = self.call("subscribe", topics=topics)
        s = Subscription(self, result["subscription"], result["topics"])
        with self._sub_lock:
            self._subscriptions[s.id] = s
            for params in self._early.pop(s.id, []):
                s._put(params)
        return s

    def close(self):
        if self._lease:
            try:
                self._lease.release()
            except (ApiError, OSError):
                pass
        try:
            self._sock.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass
        self._sock.close()
        self._reader.join(timeout=2)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


def connect(path=None, name=None, timeout=5.0):
    """A Client connected to the GUI at `path` (default_socket_path() when None)."""
    return Client(path, name, timeout)
