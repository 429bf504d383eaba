"""A small Debug Adapter Protocol client for the tests of `essaim debug` (docs/debugging.md).

It speaks DAP as an editor does: Content-Length framed JSON over the process's stdin/stdout
(`DapClient.stdio`) or over a TCP connection to `essaim debug --port N` (`DapClient.tcp`).
A reader thread parses every message the adapter sends; responses are matched to their
request by `request_seq`, events are queued in arrival order. Every wait has a timeout that
fails the test with the session's transcript (both directions) and the adapter's stderr, so
a session that hangs shows where it hung instead of stalling the suite.

Used by tests/debug/test_*.py and bench/debug_cost.py.
"""
from __future__ import annotations

import json
import re
import socket
import subprocess
import sys
import tempfile
import threading
import time
from collections import deque
from pathlib import Path

DEFAULT_TIMEOUT = 30.0  # seconds for one response or event; a run of a few hundred ticks takes less


class DapFailure(AssertionError):
    """A request that failed, a message that never came, or bytes that are not DAP."""


def _fail(message: str) -> None:
    """Fails the running test (pytest.fail under pytest, DapFailure elsewhere: the benchmark)."""
    pytest = sys.modules.get("pytest")
    if pytest is None:
        raise DapFailure(message)
    pytest.fail(message, pytrace=False)


class _Framing:
    """Reads DAP messages (`Content-Length: N\\r\\n\\r\\n` + N bytes of JSON) from a byte stream."""

    def __init__(self, read):
        self.read = read  # read(n) -> up to n bytes, b"" at the end
        self.buf = b""

    def _fill(self) -> bool:
        chunk = self.read(65536)
        if not chunk:
            return False
        self.buf += chunk
        return True

    def next(self):
        """The next message as a dict; None at the end of the stream."""
        while b"\r\n\r\n" not in self.buf:
            if not self._fill():
                if self.buf:
                    raise DapFailure(f"stream ended inside a header: {self.buf[:200]!r}")
                return None
        head, _, self.buf = self.buf.partition(b"\r\n\r\n")
        length = None
        for line in head.split(b"\r\n"):
            name, sep, value = line.partition(b":")
            if not sep or not re.fullmatch(rb"[A-Za-z][A-Za-z0-9-]*", name):
                raise DapFailure(f"not a DAP header line (something else wrote to the stream?): {line[:200]!r}")
            if name.strip().lower() == b"content-length":
                length = int(value.strip())
        if length is None:
            raise DapFailure(f"header without Content-Length: {head[:200]!r}")
        while len(self.buf) < length:
            if not self._fill():
                raise DapFailure(f"stream ended inside a body of {length} bytes")
        body, self.buf = self.buf[:length], self.buf[length:]
        return json.loads(body.decode("utf-8"))


def frame(message: dict) -> bytes:
    body = json.dumps(message).encode("utf-8")
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class DapClient:
    """One session with `essaim debug`. Start it with `stdio()` or `tcp()`."""

    def __init__(self, proc: subprocess.Popen, stderr_path: Path, timeout: float):
        self.proc = proc
        self.stderr_path = stderr_path
        self.timeout = timeout
        self.seq = 0
        self.transcript: list[tuple[str, dict]] = []
        self.responses: dict[int, dict] = {}
        self.events: deque[dict] = deque()   # not yet taken by wait_event
        self.all_events: list[dict] = []     # every event, in order
        self.closed = False                  # the adapter's side of the stream ended
        self.error: str | None = None        # a framing error from the reader
        self.cond = threading.Condition()
        self._send_bytes = None
        self._sock = None

    # ---- starting ------------------------------------------------------------------------
    @classmethod
    def stdio(cls, essaim: str, args=(), cwd=None, timeout=DEFAULT_TIMEOUT, env=None) -> "DapClient":
        """`essaim debug ARGS` with DAP on its stdin/stdout (how VS Code starts an adapter)."""
        return cls.command([essaim, "debug", *map(str, args)], cwd, timeout, env)

    @classmethod
    def command(cls, argv, cwd=None, timeout=DEFAULT_TIMEOUT, env=None) -> "DapClient":
        """Any adapter command line speaking DAP on its stdin/stdout."""
        err = _stderr_file(cwd)
        with err.open("wb") as errors:
            proc = subprocess.Popen(list(map(str, argv)), cwd=cwd, env=env, stdin=subprocess.PIPE,
                                    stdout=subprocess.PIPE, stderr=errors)
        c = cls(proc, err, timeout)
        c._send_bytes = lambda b: (proc.stdin.write(b), proc.stdin.flush())
        c._start_reader(lambda n: proc.stdout.read1(n))
        return c

    @classmethod
    def tcp(cls, essaim: str, args=(), cwd=None, port=None, timeout=DEFAULT_TIMEOUT, env=None) -> "DapClient":
        """`essaim debug ARGS --port N`, then a connection to 127.0.0.1:N (retried while the
        process starts listening)."""
        port = port or free_port()
        return cls.server([essaim, "debug", *map(str, args), "--port", str(port)], port, cwd, timeout, env)

    @classmethod
    def server(cls, argv, port: int, cwd=None, timeout=DEFAULT_TIMEOUT, env=None) -> "DapClient":
        """Any adapter command line that listens on 127.0.0.1:`port`, and a connection to it."""
        err = _stderr_file(cwd)
        with err.with_suffix(".stdout").open("wb") as output, err.open("wb") as errors:
            proc = subprocess.Popen(list(map(str, argv)), cwd=cwd, env=env, stdin=subprocess.DEVNULL,
                                    stdout=output, stderr=errors)
        c = cls(proc, err, timeout)
        c.port = port
        c._sock = c._connect(port)
        c._send_bytes = c._sock.sendall
        c._start_reader(c._sock.recv)
        return c

    def _connect(self, port: int) -> socket.socket:
        deadline = time.monotonic() + self.timeout
        while True:
            try:
                sock = socket.create_connection(("127.0.0.1", port), timeout=self.timeout)
                sock.settimeout(None)  # the reader waits as long as the session lasts; waits time out
                return sock
            except OSError as e:
                if self.proc.poll() is not None or time.monotonic() > deadline:
                    self._fail_with(f"could not connect to essaim debug on port {port}: {e}")
                time.sleep(0.05)

    def _start_reader(self, read) -> None:
        framing = _Framing(read)

        def loop():
            try:
                while True:
                    msg = framing.next()
                    if msg is None:
                        break
                    self._received(msg)
            except (DapFailure, ValueError, OSError) as e:
                with self.cond:
                    self.error = f"{type(e).__name__}: {e}"
            with self.cond:
                self.closed = True
                self.cond.notify_all()

        threading.Thread(target=loop, daemon=True).start()

    def _received(self, msg: dict) -> None:
        with self.cond:
            self.transcript.append(("<-", msg))
            if msg.get("type") == "response":
                self.responses[msg["request_seq"]] = msg
            elif msg.get("type") == "event":
                self.events.append(msg)
                self.all_events.append(msg)
            self.cond.notify_all()

    # ---- requests ------------------------------------------------------------------------
    def send(self, command: str, arguments: dict | None = None) -> int:
        """Sends a request without waiting; returns its seq (see `response`)."""
        with self.cond:
            self.seq += 1
            msg = {"seq": self.seq, "type": "request", "command": command}
            if arguments is not None:
                msg["arguments"] = arguments
            self.transcript.append(("->", msg))
        try:
            self._send_bytes(frame(msg))
        except (BrokenPipeError, ConnectionError, OSError) as e:
            self._fail_with(f"could not send {command}: {e}")
        return msg["seq"]

    def response(self, seq: int, timeout: float | None = None) -> dict:
        """The response to request `seq` (the whole message, success or not)."""
        return self._wait(lambda: self.responses.pop(seq, None), f"the response to request {seq}", timeout)

    def request(self, command: str, arguments: dict | None = None, timeout: float | None = None) -> dict:
        """Sends a request and returns its response's body; fails the test if it failed."""
        r = self.response(self.send(command, arguments), timeout)
        if not r.get("success"):
            self._fail_with(f"{command} failed: {r.get('message')} {json.dumps(r.get('body'))}")
        return r.get("body") or {}

    def request_error(self, command: str, arguments: dict | None = None, timeout: float | None = None) -> dict:
        """Sends a request that must fail; returns the failed response."""
        r = self.response(self.send(command, arguments), timeout)
        if r.get("success"):
            self._fail_with(f"{command} succeeded, expected a failure: {json.dumps(r)}")
        return r

    # ---- events ------------------------------------------------------------------------
    def wait_event(self, name: str, timeout: float | None = None, where=None) -> dict:
        """The first queued event named `name` (and for which `where(body)` holds); events
        before it stay queued."""
        def take():
            for e in self.events:
                if e.get("event") == name and (where is None or where(e.get("body") or {})):
                    self.events.remove(e)
                    return e
            return None
        return self._wait(take, f"event {name!r}", timeout)

    def stopped(self, timeout: float | None = None) -> dict:
        """The body of the next `stopped` event."""
        return self.wait_event("stopped", timeout).get("body") or {}

    def outputs(self, category: str | None = None) -> list[str]:
        """The text of every output event so far (of one category)."""
        with self.cond:
            return [e["body"]["output"] for e in self.all_events
                    if e.get("event") == "output" and (category is None or e["body"].get("category") == category)]

    def events_named(self, name: str) -> list[dict]:
        with self.cond:
            return [e for e in self.all_events if e.get("event") == name]

    def _wait(self, take, what: str, timeout: float | None):
        limit = timeout or self.timeout
        deadline = time.monotonic() + limit
        problem = None
        with self.cond:
            while problem is None:
                got = take()
                if got is not None:
                    return got
                left = deadline - time.monotonic()
                if self.closed:
                    problem = f"waiting for {what}: the adapter closed the connection"
                    problem += f" ({self.error})" if self.error else ""
                elif left <= 0:
                    problem = f"waiting for {what}: nothing after {limit:.0f} s"
                else:
                    self.cond.wait(left)
        self._fail_with(problem)

    # ---- a session as an editor drives it -------------------------------------------------
    def start(self, experiment=None, args=(), stop_on_entry=False, breakpoints=None,
              function_breakpoints=None, exceptions=None, cwd=None) -> dict:
        """initialize, launch, the breakpoints, configurationDone: the order VS Code and nvim-dap
        follow. `breakpoints` maps a source path to a list of lines or of SourceBreakpoint
        dicts. Returns {"capabilities", "breakpoints" (path -> the response's list),
        "function_breakpoints"}."""
        caps = self.request("initialize", {"clientID": "essaim-tests", "adapterID": "essaim",
                                           "linesStartAt1": True, "columnsStartAt1": True,
                                           "pathFormat": "path", "supportsVariableType": True})
        launch = {"args": [str(a) for a in args], "stopOnEntry": stop_on_entry}
        if experiment is not None:
            launch["experiment"] = str(experiment)
        if cwd is not None:
            launch["cwd"] = str(cwd)
        seq = self.send("launch", launch)
        self.wait_event("initialized")
        got = {"capabilities": caps, "breakpoints": {}, "function_breakpoints": None}
        for path, bps in (breakpoints or {}).items():
            got["breakpoints"][path] = self.set_breakpoints(path, bps)
        if function_breakpoints is not None:
            got["function_breakpoints"] = self.request(
                "setFunctionBreakpoints", {"breakpoints": function_breakpoints})["breakpoints"]
        self.request("setExceptionBreakpoints", {"filters": list(exceptions or [])})
        self.request("configurationDone")
        r = self.response(seq)
        if not r.get("success"):
            self._fail_with(f"launch failed: {r.get('message')}")
        return got

    def set_breakpoints(self, path, bps) -> list:
        bps = [b if isinstance(b, dict) else {"line": b} for b in bps]
        body = self.request("setBreakpoints", {"source": {"path": str(path)}, "breakpoints": bps,
                                               "lines": [b["line"] for b in bps]})
        return body["breakpoints"]

    def threads(self) -> dict:
        """Thread name -> id."""
        return {t["name"]: t["id"] for t in self.request("threads")["threads"]}

    def frames(self, thread: int) -> list:
        return self.request("stackTrace", {"threadId": thread})["stackFrames"]

    def scopes(self, frame: int) -> dict:
        """Scope name -> variablesReference."""
        return {s["name"]: s["variablesReference"] for s in self.request("scopes", {"frameId": frame})["scopes"]}

    def variables(self, ref: int) -> dict:
        """Name -> Variable of a scope or a table."""
        return {v["name"]: v for v in self.request("variables", {"variablesReference": ref})["variables"]}

    def evaluate(self, expression: str, frame: int | None = None, context: str = "watch") -> dict:
        args = {"expression": expression, "context": context}
        if frame is not None:
            args["frameId"] = frame
        return self.request("evaluate", args)

    def value(self, expression: str, frame: int | None = None) -> str:
        """An expression's value as the adapter shows it."""
        return self.evaluate(expression, frame)["result"]

    def resume(self, command: str, thread: int, **extra) -> dict:
        """continue / next / stepIn / stepOut / stepBack / reverseContinue / runToTick, then
        the stopped event it leads to."""
        self.request(command, {"threadId": thread, **extra})
        return self.stopped()

    def run_to_end(self, thread: int = 1, timeout: float | None = None) -> int:
        """continue, then the terminated event and the process's exit code."""
        self.request("continue", {"threadId": thread})
        return self.finish(timeout)

    def finish(self, timeout: float | None = None) -> int:
        """Waits for the run's end (terminated event, then the process's exit)."""
        self.wait_event("terminated", timeout)
        if self._sock is None and self.proc.stdin:
            self.proc.stdin.close()
        return self.wait_exit(timeout)

    # ---- ending --------------------------------------------------------------------------
    def close_connection(self) -> None:
        """Drops the connection as an editor that crashed would (no disconnect request)."""
        if self._sock is not None:
            # shutdown sends the FIN now: close() alone waits for the reader's recv to return
            try:
                self._sock.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass
            self._sock.close()
        elif self.proc.stdin:
            self.proc.stdin.close()

    def wait_exit(self, timeout: float | None = None) -> int:
        """The process's exit code; fails the test if it is still running after `timeout`."""
        try:
            return self.proc.wait(timeout=timeout or self.timeout)
        except subprocess.TimeoutExpired:
            self._fail_with(f"essaim debug still running after {timeout or self.timeout:.0f} s")

    def kill(self) -> None:
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()
        if self._sock is not None:
            self._sock.close()

    def stderr(self) -> str:
        try:
            return self.stderr_path.read_text(errors="replace")
        except OSError:
            return ""

    def transcript_text(self, last: int = 60) -> str:
        with self.cond:
            lines = [f"{d} {json.dumps(m)[:600]}" for d, m in self.transcript[-last:]]
        return "\n".join(lines)

    def _fail_with(self, message: str) -> None:
        _fail(f"{message}\n--- DAP transcript (last messages)\n{self.transcript_text()}"
              f"\n--- essaim debug stderr (end)\n{self.stderr()[-3000:]}")


def _stderr_file(cwd) -> Path:
    """Where the adapter's stderr goes: beside the run (the test's temporary folder)."""
    folder = Path(cwd) if cwd else Path(tempfile.mkdtemp(prefix="essaim-debug-"))
    n = 0
    while (folder / f"essaim-debug-{n}.stderr").exists():
        n += 1
    return folder / f"essaim-debug-{n}.stderr"
