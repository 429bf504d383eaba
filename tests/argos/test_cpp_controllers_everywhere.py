"""The rest of essaim with C++ controllers as with Lua (issue 46, item 7), on the argos3-examples
shaped project (examples_project): the Python module (poses, LEDs, errors; lua_global says the
robot runs C++), `essaim test` with a spec and a golden file, a sweep over a C++ controller's
<params> attribute, recordings with `essaim replay` and `essaim snapshot`, and the live view's
API (scene, frames, a robot's readings and LEDs, the inspector naming the C++ controller)."""
import contextlib
import json
import os
import shutil
import signal
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

from argos_projects import ESSAIM, HERE, ROOT, build_project, need_essaim, run, skip_without_python_module

pytestmark = need_essaim


@pytest.fixture(scope="module")
def examples(tmp_path_factory):
    return build_project(HERE / "examples_project", tmp_path_factory.mktemp("examples"))


def essaim(*args, cwd, timeout=300):
    return subprocess.run([ESSAIM, *map(str, args)], cwd=cwd, capture_output=True, text=True, timeout=timeout)


def test_python_module_steps_a_cpp_experiment(examples, tmp_path):
    module = Path(ESSAIM).resolve().parent / "python"
    skip_without_python_module()
    done = run(examples / "experiments/flocking.argos", "--ticks", "40", "--out", str(tmp_path / "cli"), cwd=examples)
    assert done.returncode == 0, done.stderr
    at40 = {line.split()[1]: [float.fromhex(v) for v in line.split()[2:4]]
            for line in (tmp_path / "cli/files/poses.txt").read_text().splitlines() if line.split()[0] == "40"}
    script = f"""
import json, essaim, numpy as np
out = {{}}
with essaim.Simulation('experiments/flocking.argos', seed=7) as s:
    assert s.step(40) == 40
    poses, leds = s.poses(), s.led_colors()
    out['ids'] = s.robot_ids
    out['xy'] = poses[:, :2].tolist()
    out['lit'] = int((leds.sum(axis=2) > 0).sum())
    out['errors'] = s.errors
    try:
        s.lua_global(0, 'x')
        out['lua_global'] = 'no error'
    except Exception as e:
        out['lua_global'] = str(e)
print(json.dumps(out))
"""
    done = subprocess.run([sys.executable, "-c", script], cwd=examples, capture_output=True, text=True, timeout=300,
                          env=dict(os.environ, PYTHONPATH=str(module)))
    assert done.returncode == 0, done.stderr
    out = json.loads(done.stdout.splitlines()[-1])
    assert out["errors"] == []
    assert {rid: xy for rid, xy in zip(out["ids"], out["xy"])} == at40  # the CLI's run, exactly
    assert out["lit"] > 0  # the flocking controllers light their LEDs
    assert "runs a C++ controller" in out["lua_global"] and "flocking_controller" in out["lua_global"]


SPEC = """experiment = "experiments/diffusion.argos"
ticks = 50
seeds = 2
golden = "diffusion.golden.json"
expect = [
  "each errors == 0",
  "each ticks == 50",
  "each summary.robots == 20",
]
[set]
"controllers.diffusion.params.velocity" = 8
"""


def test_essaim_test_runs_a_spec_over_a_cpp_experiment(examples, tmp_path):
    spec = examples / "diffusion.test.toml"
    spec.write_text(SPEC)
    first = essaim("test", spec, "--update", "-j", "2", "--out", tmp_path / "t1", cwd=examples)
    assert first.returncode == 0, first.stdout + first.stderr
    assert (examples / "diffusion.golden.json").is_file()
    again = essaim("test", spec, "-j", "2", "--out", tmp_path / "t2", cwd=examples)
    assert again.returncode == 0, again.stdout + again.stderr
    assert "5 of 5 expectations hold" in again.stdout  # every run exits 0, the three rows, the golden
    # A change of the C++ controller's parameter changes the run: the golden run differs.
    spec.write_text(SPEC.replace("velocity\" = 8", "velocity\" = 3"))
    changed = essaim("test", spec, "--out", tmp_path / "t3", cwd=examples)
    assert changed.returncode == 1 and "golden" in changed.stdout, changed.stdout + changed.stderr


def test_a_sweep_over_a_cpp_controllers_parameter(examples, tmp_path):
    sweep = tmp_path / "velocity.toml"
    sweep.write_text(f"""experiment = "{examples / 'experiments/diffusion.argos'}"
workdir = "{examples}"
ticks = 30
seeds = 1
[params]
"controllers.diffusion.params.velocity" = [0, 10]
""")
    done = subprocess.run([sys.executable, str(ROOT / "scripts/sweep.py"), str(sweep), "-j", "2", "--no-progress",
                           "--essaim", ESSAIM, "--out", str(tmp_path / "out")],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
    runs = tmp_path / "out" / "runs"
    moved = {}
    for velocity in (0, 10):
        lines = (runs / f"velocity=0__seed=1" if velocity == 0 else runs / "velocity=10__seed=1")
        rows = [line.split() for line in (lines / "files/poses.txt").read_text().splitlines()]
        first = {r[1]: (float.fromhex(r[2]), float.fromhex(r[3])) for r in rows if r[0] == "1"}
        last = {r[1]: (float.fromhex(r[2]), float.fromhex(r[3])) for r in rows if r[0] == "30"}
        moved[velocity] = sum(abs(last[k][0] - first[k][0]) + abs(last[k][1] - first[k][1]) for k in first)
    assert moved[0] == 0 and moved[10] > 1  # <params velocity> reached the C++ controllers
    # The sweep's resume check sees the controller's library among the run's inputs: a rebuilt
    # library redoes the runs.
    inputs = json.loads((runs / "velocity=10__seed=1" / "summary.json").read_text())["inputs"]
    assert any("libdiffusion" in i["path"] for i in inputs), inputs


def test_a_cpp_run_is_recorded_replayed_and_drawn_as_its_lua_twin(examples, tmp_path):
    for name in ("diffusion", "diffusion_lua"):
        done = run(examples / f"experiments/{name}.argos", "--ticks", "30", "--record", "--out", str(tmp_path / name),
                   cwd=examples)
        assert done.returncode == 0, done.stderr
        assert essaim("replay", tmp_path / name, cwd=tmp_path).returncode == 0
        drawn = essaim("snapshot", tmp_path / name, "--tick", "30", "-o", tmp_path / f"{name}.png", cwd=tmp_path)
        if "without Cairo" not in drawn.stderr:
            assert drawn.returncode == 0, drawn.stderr
            assert (tmp_path / f"{name}.png").read_bytes()[:4] == b"\x89PNG"
    assert (tmp_path / "diffusion/replay.html").stat().st_size > 1000
    # The same moves as the Lua twin's: the recordings' frames are the same.
    module = Path(ESSAIM).resolve().parent / "python"
    # Under ASan the interpreter needs the sanitizer's runtime preloaded (python_module covers it).
    if any(module.glob("essaim*.so")) and os.environ.get("ESSAIM_SANITIZED") != "1":
        script = ("import essaim, numpy as np, sys\n"
                  "a, b = (essaim.read_recording(p) for p in sys.argv[1:])\n"
                  "print(np.array_equal(a.poses, b.poses), a.poses.shape)\n")
        done = subprocess.run([sys.executable, "-c", script, str(tmp_path / "diffusion"),
                               str(tmp_path / "diffusion_lua")], capture_output=True, text=True, timeout=120,
                              env=dict(os.environ, PYTHONPATH=str(module)))
        assert done.returncode == 0, done.stderr
        assert done.stdout.startswith("True"), done.stdout


def call(base, path, token, body=None):
    req = urllib.request.Request(base + path, data=body.encode() if body is not None else None,
                                 headers={"Authorization": "Bearer " + token})
    with urllib.request.urlopen(req, timeout=10) as r:
        return json.loads(r.read() or b"null")


@contextlib.contextmanager
def serving(project):
    proc = subprocess.Popen([ESSAIM, "serve", "experiments/flocking.argos", "--port", "0"], cwd=project,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        url = proc.stdout.readline().strip()
        assert "/?token=" in url, proc.stderr.read() if proc.poll() is not None else url
        yield url
    finally:
        if proc.poll() is None:
            proc.send_signal(signal.SIGINT)
            proc.wait(timeout=30)


def test_the_live_view_serves_a_cpp_swarm(examples):
    with serving(examples) as url:
        base, token = url.split("/?token=")
        state, end = None, time.monotonic() + 30
        while not state and time.monotonic() < end:  # the first state comes once the world is made
            state = call(base, "/api/state", token)
            time.sleep(0.1)
        assert state and len(state["robots"]) == 12
        assert call(base, "/api/scene", token)
        call(base, "/api/control", token, body='{"cmd": "step", "ticks": 12}')
        end = time.monotonic() + 30
        while (state := call(base, "/api/state", token))["tick"] < 12 and time.monotonic() < end:
            time.sleep(0.05)
        assert state["tick"] == 12 and state["error"] == ""
        with urllib.request.urlopen(urllib.request.Request(base + "/api/events?token=" + token), timeout=10) as r:
            assert r.readline().startswith(b"event: frame")
        robot = call(base, "/api/robot?robot=3", token)
        assert robot["controller_ok"] and robot["controller"]["kind"] == "cpp"
        assert robot["controller"]["label"] == "flocking_controller"
        assert "C++ controller" in robot["controller"]["note"]
        assert robot["globals"] == {}  # no Lua globals to show
        readings = robot["readings"]
        assert len(readings["range_and_bearing"]) > 0  # the flock hears itself
        assert readings["positioning"]["position"]["x"] == pytest.approx(robot["pose"]["x"], abs=1e-3)
        assert any(any(c) for c in robot["actuators"]["leds"])  # LEDs lit by the controller


def test_the_live_pages_inspector_says_the_robot_runs_cpp(examples):
    sync_api = pytest.importorskip("playwright.sync_api", reason="playwright missing: install scripts/requirements.txt")
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        pytest.skip("chromium missing: scripts/setup.sh installs Debian's chromium")
    with serving(examples) as url, sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=chromium, args=["--headless", "--no-sandbox", "--disable-gpu"])
        page = browser.new_page(viewport={"width": 1200, "height": 760})
        errors = []
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto(url)
        page.wait_for_function("window.essaimLive && essaimLive.frame() && essaimLive.frame().robots.length === 12",
                               timeout=20000)
        page.wait_for_function("document.getElementById('view').dataset.robotCount === '12'", timeout=20000)
        pos = page.evaluate("essaimLive.robotCanvasPosition(2)")
        page.click("#view", position={"x": pos["x"], "y": pos["y"]})
        page.wait_for_function("document.getElementById('inspector').textContent.includes('runs a C++ controller')",
                               timeout=20000)
        text = page.text_content("#inspector")
        assert text.startswith("fb2") and "range_and_bearing" in text and "leds" in text
        assert errors == []
        browser.close()


LUA_LOOP = """
function post_step()
  if experiment.tick ~= 3 then return end
  for _, r in ipairs(experiment.robots) do
    local ok, err = pcall(function() r:set_lua_global("mark", r.index) end)
    log(r.id .. " set " .. tostring(ok) .. (ok and "" or (" " .. err)))
    log(r.id .. " reads " .. tostring(r:lua_global("mark")))
  end
end
"""


def test_lua_loop_functions_reach_lua_robots_and_say_a_cpp_one_has_no_globals(examples, tmp_path):
    (examples / "experiments/mixed_loop.lua").write_text(LUA_LOOP)
    text = (examples / "experiments/mixed.argos").read_text()
    argos = examples / "experiments/mixed_lua_loop.argos"
    argos.write_text(text.replace('<loop_functions library="build/loop_functions/pose_log/libpose_log" label="pose_log"/>',
                                  '<loop_functions script="experiments/mixed_loop.lua"/>'))
    done = run(argos, "--ticks", "5", "--out", str(tmp_path / "out"), cwd=examples)
    assert done.returncode == 0, done.stderr
    assert "lua0 set true" in done.stdout and "lua0 reads " in done.stdout and "lua0 reads nil" not in done.stdout
    assert "cpp0 reads nil" in done.stdout, done.stdout
    assert "cpp0 set false" in done.stdout and "runs a C++ controller (ground_forager_controller)" in done.stdout
