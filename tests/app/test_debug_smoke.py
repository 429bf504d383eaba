"""`essaim debug` driven by a few DAP messages (the full client suite is tests/debug/): a
breakpoint with a condition, a look at the frame, a step back to the previous tick, a reverse
continue to the previous hit, and the
run's end with the same summary as `essaim run`; a client that just leaves."""
import json
import subprocess

from clitest import ESSAIM, argos, need_essaim, run, write

COUNTER = """local count = 0
function init() end
function step()
  count = count + 1
  robot.wheels.set_velocity(5, 5)
end
"""


class Dap:
    """A minimal DAP client over the process's stdin/stdout."""

    def __init__(self, folder, *args):
        self.p = subprocess.Popen([ESSAIM, "debug", *args], cwd=folder, stdin=subprocess.PIPE,
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        self.seq = 0
        self.seen = []

    def send(self, command, **arguments):
        self.seq += 1
        body = json.dumps({"seq": self.seq, "type": "request", "command": command,
                           "arguments": arguments}).encode()
        self.p.stdin.write(b"Content-Length: %d\r\n\r\n%s" % (len(body), body))
        self.p.stdin.flush()
        return self.seq

    def read(self):
        header = b""
        while not header.endswith(b"\r\n\r\n"):
            byte = self.p.stdout.read(1)
            assert byte, "essaim debug closed its output"
            header += byte
        length = int(header.split(b"Content-Length:")[1].split(b"\r\n")[0])
        return json.loads(self.p.stdout.read(length))

    def request(self, command, **arguments):
        seq = self.send(command, **arguments)
        while True:
            m = self.read()
            if m["type"] == "response" and m["request_seq"] == seq:
                return m
            self.seen.append(m)

    def event(self, name):
        for i, m in enumerate(self.seen):
            if m.get("event") == name:
                return self.seen.pop(i)
        while True:
            m = self.read()
            if m.get("event") == name:
                return m
            self.seen.append(m)


def start(tmp_path, *args):
    write(tmp_path, {"e.argos": argos(length=20), "c.lua": COUNTER})
    dap = Dap(tmp_path, "e.argos", "--out", "dbg", *args)
    assert dap.request("initialize", adapterID="essaim")["body"]["supportsStepBack"]
    assert dap.request("launch")["success"]
    dap.event("initialized")
    return dap


@need_essaim
def test_a_conditional_breakpoint_a_step_back_and_the_same_summary_as_run(tmp_path):
    dap = start(tmp_path, "--record")
    bps = dap.request("setBreakpoints", source={"path": "c.lua"},
                      breakpoints=[{"line": 4, "condition": 'robot.id == "fb1" and tick == 5'}])
    assert bps["body"]["breakpoints"][0]["verified"]
    dap.request("configurationDone")
    stopped = dap.event("stopped")["body"]
    assert (stopped["reason"], stopped["threadId"]) == ("breakpoint", 3)
    frame = dap.request("stackTrace", threadId=3)["body"]["stackFrames"][0]
    assert (frame["name"], frame["line"]) == ("step", 4)
    assert dap.request("evaluate", expression="count", frameId=frame["id"])["body"]["result"] == "4"
    dap.request("stepBack", threadId=3)
    assert dap.event("stopped")["body"]["reason"] == "step"
    frame = dap.request("stackTrace", threadId=3)["body"]["stackFrames"][0]
    assert dap.request("evaluate", expression="count", frameId=frame["id"])["body"]["result"] == "3"
    dap.request("setBreakpoints", source={"path": "c.lua"}, breakpoints=[{"line": 4, "condition": 'robot.id == "fb0"'}])
    dap.request("reverseContinue", threadId=3)  # fb0's hit at tick 3: the last one before here
    assert dap.event("stopped")["body"] == {"reason": "breakpoint", "threadId": 2, "allThreadsStopped": True,
                                           "description": "breakpoint"}
    frame = dap.request("stackTrace", threadId=2)["body"]["stackFrames"][0]
    assert dap.request("evaluate", expression="count", frameId=frame["id"])["body"]["result"] == "3"
    dap.request("setBreakpoints", source={"path": "c.lua"}, breakpoints=[])
    dap.request("continue", threadId=3)
    assert dap.event("exited")["body"]["exitCode"] == 0
    dap.event("terminated")
    dap.request("disconnect")
    assert dap.p.wait(timeout=60) == 0
    debugged = json.loads((tmp_path / "dbg" / "summary.json").read_text())
    assert debugged["debug"] == {"divergences": []}
    _, ran = run(tmp_path, "e.argos", "--record", out="ran")
    assert debugged["ticks"] == ran["ticks"] == 200 and debugged["status"] == ran["status"] == "ok"
    assert (tmp_path / "dbg" / "recording.bin").read_bytes() == (tmp_path / "ran" / "recording.bin").read_bytes()


@need_essaim
def test_a_client_that_leaves_lets_the_run_end_with_its_summary(tmp_path):
    dap = start(tmp_path)
    dap.request("configurationDone")
    dap.p.stdin.close()
    assert dap.p.wait(timeout=60) == 0
    assert json.loads((tmp_path / "dbg" / "summary.json").read_text())["status"] == "ok"
