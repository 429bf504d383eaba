"""`essaim serve`: the HTTP API (token, Host and Origin checks, control commands) and the live
page in headless Chromium (Playwright): robots move after play, the inspector shows a Lua
global, saving the controller reloads it (run counter, behaviour), a syntax error shows as
file:line on the page and a fix clears it, with no page errors; a foot-bot the loop functions
add appears on the page and in the API, its log lines under its id.

Needs Python's `playwright` and Debian's chromium, as test_replay_browser.py.
ESSAIM_DOC_SCREENSHOTS=1 also writes the screenshot docs/live.md shows (docs/img/live.png).
"""
import json
import math
import os
import shutil
import signal
import subprocess
import time
import urllib.error
import urllib.request
from pathlib import Path

import pytest

from test_replay_browser import CHROMIUM_ARGS, chromium_path

ROOT = Path(__file__).resolve().parents[2]

FORWARD = """
mode = "forward"
state = {trips = 0, target = {x = 1.5, y = -2}}
function init() robot.leds.set_all_colors("green") end
function step()
  state.trips = state.trips + 1
  robot.wheels.set_velocity(10, 10)
  if state.trips == 3 then log("three steps") end
end
"""

SPIN = FORWARD.replace('mode = "forward"', 'mode = "spin"').replace(
    "set_velocity(10, 10)", "set_velocity(-10, 10)").replace('"green"', '"blue"')

BROKEN = "function step()\n  robot.wheels.set_velocity(1, 1\nend\n"

LOOP = """
function floor_color(x, y)
  if x < -1 and y < -1 then return 40, 40, 40 end
  return 255, 255, 255
end
function post_step()
  if experiment.tick % 5 == 0 then
    experiment.timeseries({{"tick", experiment.tick}, {"wave", math.sin(experiment.tick / 10)}})
  end
end
"""


def experiment(script: Path, loop: Path) -> str:
    bots = "".join(f'<foot-bot id="fb{i}"><body position="{x},{y},0" orientation="{yaw},0,0"/>'
                   f'<controller config="c"/></foot-bot>'
                   for i, (x, y, yaw) in enumerate([(-2, -1, 0), (-1, 0.8, 45), (0, -1, 90), (1, 0.8, 180),
                                                    (2, -1.2, 270)]))
    return f"""<?xml version="1.0" ?>
<argos-configuration>
  <framework><experiment length="0" ticks_per_second="10" random_seed="3"/></framework>
  <controllers>
    <lua_controller id="c">
      <actuators><differential_steering implementation="default"/>
        <leds implementation="default" medium="leds"/></actuators>
      <sensors><positioning implementation="default"/></sensors>
      <params script="{script}"/>
    </lua_controller>
  </controllers>
  <loop_functions script="{loop}"/>
  <arena size="6,4,1" center="0,0,0.5">
    <floor id="f" source="loop_functions" pixels_per_meter="20"/>
    <box id="crate" size="0.3,0.2,0.2" movable="true" mass="1"><body position="2,1,0" orientation="20,0,0"/></box>
    {bots}
  </arena>
  <physics_engines><dynamics2d id="dyn2d"/></physics_engines>
  <media><led id="leds"/></media>
</argos-configuration>
"""


def save(path: Path, text: str):
    """As an editor does: a temporary file renamed over the original."""
    tmp = path.with_name(path.name + ".tmp~")
    tmp.write_text(text)
    os.replace(tmp, path)


def serve(essaim, tmp_path, loop_text=LOOP):
    ctrl, loop = tmp_path / "ctrl.lua", tmp_path / "loop.lua"
    ctrl.write_text(FORWARD)
    loop.write_text(loop_text)
    argos = tmp_path / "live.argos"
    argos.write_text(experiment(ctrl, loop))
    proc = subprocess.Popen([essaim, "serve", str(argos), "--port", "0"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    url = proc.stdout.readline().strip()
    assert url.startswith("http://127.0.0.1:") and "/?token=" in url, (url, proc.stderr.read() if proc.poll() else "")
    base, token = url.split("/?token=")
    return {"proc": proc, "url": url, "base": base, "token": token, "ctrl": ctrl}


@pytest.fixture
def served(essaim, tmp_path):
    s = serve(essaim, tmp_path)
    yield s
    if s["proc"].poll() is None:
        s["proc"].send_signal(signal.SIGINT)
        s["proc"].wait(timeout=30)


def call(base, path, token=None, body=None, headers=None):
    h = dict(headers or {})
    if token:
        h["Authorization"] = "Bearer " + token
    req = urllib.request.Request(base + path, data=body.encode() if body is not None else None, headers=h)
    try:
        with urllib.request.urlopen(req, timeout=10) as r:
            return r.status, json.loads(r.read() or b"null")
    except urllib.error.HTTPError as e:
        return e.code, json.loads(e.read() or b"null")


def wait_for(fn, timeout=20):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        value = fn()
        if value:
            return value
        time.sleep(0.05)
    raise AssertionError("timed out waiting")


def test_api_needs_the_token_and_its_own_origin(served):
    base, token = served["base"], served["token"]
    assert call(base, "/api/state")[0] == 401
    assert call(base, "/api/state", token="nope")[0] == 403
    status, body = call(base, "/api/state", token=token, headers={"Origin": "http://evil.example"})
    assert status == 403 and "Origin" in body["error"]
    assert call(base, "/api/state", token=token, headers={"Host": "evil.example"})[0] == 403
    status, state = call(base, "/api/state?token=" + token)
    assert status == 200
    assert state["tick"] == 0 and state["run"] == 1 and state["paused"] is True and state["error"] == ""
    assert [r["id"] for r in state["robots"]] == [f"fb{i}" for i in range(5)]
    for bad, why in (("{", "invalid JSON"), ('{"cmd": "fly"}', "unknown cmd"), ('{"cmd": "step", "ticks": -2}', "ticks")):
        status, body = call(base, "/api/control", token=token, body=bad)
        assert status == 400 and why in body["error"], body
    status, _ = call(base, "/api/control", token=token, body='{"cmd": "step", "ticks": 7}')
    assert status == 200
    state = wait_for(lambda: (s := call(base, "/api/state", token=token)[1])["tick"] == 7 and s["paused"] and s)
    assert state["robots"][2]["y"] > -1  # fb2 faces +y and drove
    status, robot = call(base, "/api/robot?robot=2", token=token)
    assert status == 200 and robot["id"] == "fb2" and robot["globals"]["mode"] == "forward"
    assert robot["globals"]["state"]["trips"] == 7
    assert [line["text"] for line in robot["log"]] == ["three steps"]
    assert call(base, "/api/robot?robot=99", token=token)[0] == 404
    # A client that leaves in the middle of the event stream: the server serves on.
    with urllib.request.urlopen(urllib.request.Request(base + "/api/events?token=" + token), timeout=10) as r:
        assert r.readline().startswith(b"event: frame")
    assert call(base, "/api/state", token=token)[0] == 200
    served["proc"].send_signal(signal.SIGINT)
    assert served["proc"].wait(timeout=30) == 0


@pytest.fixture(scope="module")
def browser():
    sync_api = pytest.importorskip("playwright.sync_api", reason="playwright missing: install scripts/requirements.txt")
    exe = chromium_path()
    if not exe:
        pytest.skip("chromium missing: scripts/setup.sh installs Debian's chromium")
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=exe, args=CHROMIUM_ARGS)
        yield b
        b.close()


def positions(page):
    return page.evaluate("essaimLive.frame().robots.map(r => [r.x, r.y, r.yaw])")


def test_live_page_plays_inspects_and_reloads_on_save(served, browser, tmp_path):
    page = browser.new_page(viewport={"width": 1200, "height": 760})
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.goto(served["url"])
    page.wait_for_function("window.essaimLive && essaimLive.frame() && essaimLive.frame().robots.length === 5",
                           timeout=20000)
    page.wait_for_function("document.getElementById('view').dataset.robotCount === '5'", timeout=10000)
    assert page.text_content("#state") == "paused" and page.text_content("#tick") == "0"
    start = positions(page)

    page.select_option("#speed", "10")
    page.click("#play")
    page.wait_for_function("Number(document.getElementById('tick').textContent) >= 20", timeout=20000)
    page.click("#play")  # pause
    page.wait_for_function("document.getElementById('state').textContent === 'paused'", timeout=10000)
    moved = positions(page)
    assert all(math.hypot(b[0] - a[0], b[1] - a[1]) > 0.05 for a, b in zip(start, moved))
    page.wait_for_function("essaimLive.series().rows > 0", timeout=10000)  # charts get the time series

    pos = page.evaluate("essaimLive.robotCanvasPosition(1)")
    page.click("#view", position={"x": pos["x"], "y": pos["y"]})
    page.wait_for_function("document.getElementById('inspector').textContent.includes('\"forward\"')", timeout=10000)
    assert page.text_content("#inspector").startswith("fb1")
    page.wait_for_function("document.getElementById('log').textContent.includes('three steps')", timeout=10000)
    shot = tmp_path / "live.png"
    page.screenshot(path=str(shot))
    if os.environ.get("ESSAIM_DOC_SCREENSHOTS") == "1":
        shutil.copy(shot, ROOT / "docs" / "img" / "live.png")

    # Save a new behaviour: reloaded and reset, run 2, robots spin in place.
    save(served["ctrl"], SPIN)
    page.wait_for_function("document.getElementById('run').textContent === '2'", timeout=20000)
    assert page.text_content("#tick") == "0"
    before = positions(page)
    page.click("#runN")  # 100 ticks
    page.wait_for_function("Number(document.getElementById('tick').textContent) === 100", timeout=30000)
    after = positions(page)
    assert all(math.hypot(b[0] - a[0], b[1] - a[1]) < 0.02 for a, b in zip(before, after)), (before, after)
    assert any(abs(b[2] - a[2]) > 0.5 for a, b in zip(before, after))
    page.wait_for_function("document.getElementById('inspector').textContent.includes('\"spin\"')", timeout=10000)

    # A syntax error: shown as file:line, the last good experiment stays; a fix clears it.
    save(served["ctrl"], BROKEN)
    page.wait_for_function("document.getElementById('error').textContent.includes('ctrl.lua:3:')", timeout=20000)
    assert page.text_content("#run") == "2"
    state = call(served["base"], "/api/state", token=served["token"])[1]
    assert "ctrl.lua:3:" in state["error"] and state["run"] == 2
    save(served["ctrl"], FORWARD)
    page.wait_for_function("document.getElementById('run').textContent === '3'", timeout=20000)
    page.wait_for_function("document.getElementById('error').textContent === ''", timeout=10000)
    assert errors == []
    page.close()


JOINING = LOOP + """
function pre_step()
  if experiment.tick == 4 then  -- before the controllers' step: it steps from tick 4 on
    experiment.add_entity("foot-bot", {id = "newcomer", controller = "c", position = {0, 1.5}, orientation = 90})
    experiment.add_entity("cylinder", {id = "drum", position = {-2, -1.5}, radius = 0.1, height = 0.2,
                                       movable = true, mass = 0.5})
  end
  if experiment.tick == 6 then experiment.remove_entity(experiment.entities("box")[1]) end
end
"""


def test_live_view_shows_a_robot_added_during_the_run(essaim, browser, tmp_path):
    served = serve(essaim, tmp_path, JOINING)
    try:
        base, token = served["base"], served["token"]
        page = browser.new_page(viewport={"width": 1200, "height": 760})
        errors = []
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto(served["url"])
        page.wait_for_function("document.getElementById('view').dataset.robotCount === '5'", timeout=20000)
        pos = page.evaluate("essaimLive.robotCanvasPosition(4)")  # fb4 selected before the newcomer joins
        page.click("#view", position={"x": pos["x"], "y": pos["y"]})
        page.wait_for_function("document.getElementById('inspector').textContent.startsWith('fb4')", timeout=10000)
        assert call(base, "/api/control", token=token, body='{"cmd": "step", "ticks": 8}')[0] == 200
        page.wait_for_function("document.getElementById('view').dataset.robotCount === '6'", timeout=20000)
        state = wait_for(lambda: (s := call(base, "/api/state", token=token)[1])["tick"] == 8 and s)
        assert [r["id"] for r in state["robots"]] == [f"fb{i}" for i in range(5)] + ["newcomer"]
        assert state["robots"][5]["y"] > 1.5  # it drove north from where it was added
        assert page.text_content("#inspector").startswith("fb4")  # the selection stays on its robot
        status, robot = call(base, "/api/robot?robot=5", token=token)
        assert status == 200 and robot["id"] == "newcomer" and robot["globals"]["state"]["trips"] == 5
        lines = call(base, "/api/log?from=0", token=token)[1]["lines"]
        assert [(l["who"], l["tick"]) for l in lines if l["text"] == "three steps"] == \
            [(f"fb{i}", 3) for i in range(5)] + [("newcomer", 6)]
        page.wait_for_function("document.getElementById('log').textContent.includes('newcomer] three steps')",
                               timeout=10000)
        # The cylinder added at tick 4 and the crate removed at tick 6 reach the page's scene.
        scene = call(base, "/api/scene", token=token)[1]
        assert [o["id"] for o in scene["obstacles"]] == ["drum"] and state["scene"] >= 2
        assert [m[0] for m in state["movable"]] == [0]  # the drum, by its index in the new scene
        page.wait_for_function("document.getElementById('view').dataset.obstacles === '1'", timeout=10000)
        assert errors == []
        page.close()
    finally:
        served["proc"].send_signal(signal.SIGINT)
        served["proc"].wait(timeout=30)


def test_run_watch_reruns_on_save_until_ctrl_c(essaim, tmp_path):
    import threading
    ctrl, loop, helper = tmp_path / "ctrl.lua", tmp_path / "loop.lua", tmp_path / "helper.lua"
    helper.write_text("return {speed = 10}\n")
    ctrl.write_text("local h = require('helper')\nfunction step() robot.wheels.set_velocity(h.speed, h.speed) end\n")
    loop.write_text(LOOP)
    argos = tmp_path / "w.argos"
    argos.write_text(experiment(ctrl, loop).replace('length="0"', 'length="3"'))
    out = tmp_path / "out"
    proc = subprocess.Popen([essaim, "run", str(argos), "--watch", "--out", str(out)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    lines = {"out": [], "err": []}
    for name, stream in (("out", proc.stdout), ("err", proc.stderr)):
        threading.Thread(target=lambda n=name, s=stream: [lines[n].append(x) for x in s], daemon=True).start()
    try:
        waiting = lambda k: sum("watching" in x for x in lines["err"]) >= k
        wait_for(lambda: waiting(1), timeout=60)
        assert len(lines["out"]) == 1 and "30 ticks" in lines["out"][0]
        first = json.loads((out / "summary.json").read_text())
        save(helper, "return {speed = \n")  # a broken module: that run fails, watching goes on
        wait_for(lambda: waiting(2), timeout=60)
        assert any("helper.lua:2:" in x for x in lines["err"]), lines["err"]
        save(helper, "return {speed = 3}\n")  # the fix is seen: the module is still watched
        wait_for(lambda: waiting(3), timeout=60)
        assert len(lines["out"]) == 2, lines["out"]
    finally:
        proc.send_signal(signal.SIGINT)
        rc = proc.wait(timeout=30)
    assert rc == 0, lines["err"]
    last = json.loads((out / "summary.json").read_text())
    assert last["status"] == "ok" and last["ticks"] == first["ticks"] == 30


def test_replay_page_charts_the_runs_time_series(essaim, browser, tmp_path):
    ctrl, loop = tmp_path / "ctrl.lua", tmp_path / "loop.lua"
    ctrl.write_text(FORWARD)
    loop.write_text(LOOP)
    argos = tmp_path / "r.argos"
    argos.write_text(experiment(ctrl, loop).replace('length="0"', 'length="10"'))
    out = tmp_path / "run"
    subprocess.run([essaim, "run", str(argos), "--record", "--quiet", "--out", str(out)], check=True, timeout=120)
    subprocess.run([essaim, "replay", str(out)], check=True, capture_output=True, timeout=60)
    page = browser.new_page(viewport={"width": 1000, "height": 760})
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto((out / "replay.html").as_uri())
    page.wait_for_function("window.essaimReplay && essaimReplay.ready", timeout=30000)
    assert page.evaluate("essaimReplay.series()") == {"columns": ["tick", "wave"], "rows": 20}
    assert "wave" in page.text_content("#charts .legend")
    # The legend gives the value at the tick shown.
    page.evaluate("essaimReplay.setFrame(50)")
    # The legend is redrawn at the next animation frame, not within setFrame.
    want = str(round(math.sin(5), 3))
    page.wait_for_function(f"document.querySelector('#charts .legend b').textContent === '{want}'", timeout=10000)
    assert page.text_content("#charts .legend b") == want
    assert errors == []
    page.close()


def test_serve_refuses_a_missing_file_and_a_bad_port(essaim, tmp_path):
    missing = subprocess.run([essaim, "serve", str(tmp_path / "nope.argos")], capture_output=True, text=True,
                             timeout=30)
    assert missing.returncode == 2 and "no such file" in missing.stderr
    (tmp_path / "x.argos").write_text("<argos-configuration>")
    bad = subprocess.run([essaim, "serve", str(tmp_path / "x.argos"), "--port", "70000"], capture_output=True,
                         text=True, timeout=30)
    assert bad.returncode == 2 and "--port" in bad.stderr
