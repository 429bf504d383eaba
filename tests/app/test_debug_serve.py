"""`essaim debug --serve`: the live page's /api/state follows the debug session: paused by the
debugger at the stop's tick, the selected thread's robot, running again after a continue, and
the earlier tick after a step back (the copy woken from a checkpoint publishes once live), the
run's end; --serve in launch's args."""
import json
import re
import time
import urllib.error
import urllib.request

from clitest import need_essaim
from test_debug_smoke import start


def get(url, path):
    base, token = re.match(r"(http://[^/]+)/\?token=(\w+)", url).groups()
    request = urllib.request.Request(base + path, headers={"Authorization": "Bearer " + token})
    with urllib.request.urlopen(request, timeout=10) as r:
        return json.loads(r.read())


def debug_state(url, wanted):
    """The frame's "debug" once it has every field of `wanted`: a stop's frame is in before
    the stopped event reaches the client, but a new selection's or a resume's comes right
    after the request's response."""
    for _ in range(200):
        d = (get(url, "/api/state") or {}).get("debug")
        if d and all(d.get(k) == v for k, v in wanted.items()):
            return d
        time.sleep(0.05)
    raise AssertionError(f"no frame with {wanted}; the last: {d}")


def live_view_url(dap):
    while True:
        text = dap.event("output")["body"]["output"]
        if "live view:" in text:
            return text.split("live view: ")[1].strip()


@need_essaim
def test_the_page_shows_the_stop_the_selected_robot_and_a_step_back(tmp_path):
    dap = start(tmp_path, "--serve", "0")
    dap.request("setBreakpoints", source={"path": "c.lua"},
                breakpoints=[{"line": 4, "condition": 'robot.id == "fb1" and tick == 5'}])
    dap.request("configurationDone")
    url = live_view_url(dap)
    assert dap.event("stopped")["body"]["threadId"] == 3
    d = debug_state(url, {"paused": True})
    assert (d["tick"], d["robot"], d["robot_index"], d["boundary"]) == (5, "fb1", 1, False)
    assert get(url, "/api/scene")["ids"] == ["fb0", "fb1", "fb2"]
    try:
        urllib.request.urlopen(url.split("?")[0] + "api/state", timeout=10)
        assert False, "the state without the token"
    except urllib.error.HTTPError as e:
        assert e.code == 401
    dap.request("stackTrace", threadId=2)  # the user looks at fb0's thread
    assert debug_state(url, {"paused": True, "robot": "fb0"})["robot_index"] == 0
    dap.request("stepBack", threadId=3)
    assert dap.event("stopped")["body"]["reason"] == "step"
    d = debug_state(url, {"paused": True, "tick": 4})
    assert (d["robot"], d["selected"]) == ("fb1", "fb1")
    dap.request("setBreakpoints", source={"path": "c.lua"}, breakpoints=[])
    dap.request("continue", threadId=3)
    assert debug_state(url, {"paused": False})["robot"] == ""
    assert dap.event("exited")["body"]["exitCode"] == 0
    assert debug_state(url, {"ended": True})["tick"] == 200
    dap.event("terminated")
    dap.request("disconnect")
    assert dap.p.wait(timeout=60) == 0


@need_essaim
def test_serve_in_launch_args(tmp_path):
    from test_debug_smoke import COUNTER, Dap
    from clitest import argos, write
    write(tmp_path, {"e.argos": argos(length=1), "c.lua": COUNTER})
    dap = Dap(tmp_path)
    dap.request("initialize", adapterID="essaim")
    assert dap.request("launch", experiment="e.argos", args=["--serve", "0", "--out", "dbg"],
                       stopOnEntry=True)["success"]
    dap.event("initialized")
    dap.request("configurationDone")
    url = live_view_url(dap)
    assert dap.event("stopped")["body"]["reason"] == "entry"
    d = debug_state(url, {"paused": True})
    assert (d["tick"], d["boundary"], d["robot"]) == (1, True, "fb0")
    dap.request("disconnect")
    assert dap.p.wait(timeout=60) == 0
