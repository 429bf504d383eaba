"""`essaim debug --serve PORT`: the live view of `essaim serve` (docs/live.md) shows the same
session: while it is paused before tick 12 the page's state is that of tick 11, paused. The
page's address, with its token, is given to the editor in the debug console (stdout is the
protocol's), as `essaim serve` prints it on its terminal."""
import json
import re
import urllib.error
import urllib.request

from dap_client import free_port
from debug_support import SHORT


def get(url: str, token: str | None = None):
    """(status, JSON body) of a GET."""
    headers = {"Authorization": f"Bearer {token}"} if token else {}
    try:
        with urllib.request.urlopen(urllib.request.Request(url, headers=headers), timeout=10) as r:
            return r.status, json.loads(r.read())
    except urllib.error.HTTPError as e:
        return e.code, None


def test_the_live_view_shows_the_paused_session(argos, tmp_path, session):
    port = free_port()
    dap = session([argos, *SHORT, "--out", tmp_path / "dbg", "--serve", port])
    dap.start(stop_on_entry=True)
    thread = dap.stopped()["threadId"]
    assert dap.resume("runToTick", thread, tick=12)["reason"] == "goto"

    base = f"http://127.0.0.1:{port}"
    try:
        status, _ = get(base + "/api/state")
    except OSError as e:
        raise AssertionError(f"nothing answers on --serve's port {port}: {e}") from None
    assert status == 401  # a token is needed, as for essaim serve
    urls = [m.group(0) for t in dap.outputs() for m in [re.search(rf"{base}/\?token=[\w-]+", t)] if m]
    assert urls, f"no live view address among the output events: {dap.outputs()}"
    status, state = get(base + "/api/state", urls[0].split("token=")[1])
    assert status == 200 and state["paused"] is True and state["tick"] == 11
    assert [r["id"] for r in state["robots"]] == ["fb0", "fb1", "fb2", "fb3", "fb4"]
    dap.request("terminate")
    assert dap.finish() == 0
