"""What a hostile audit broke, one test per numbered case (docs/safety.md).

Every run is made under a 4 GiB address-space limit (not under ASan, whose shadow memory
reserves terabytes; ESSAIM_SANITIZED=1) and a timeout: a crash, an abort, a hang or a
blow-up fails the test. Each case is its own ctest (tests/hardening/CMakeLists.txt).
"""

import json
import os
import resource
import signal
import struct
import subprocess
import sys
import time
import zlib
from pathlib import Path

import pytest

ESSAIM = os.environ.get("ESSAIM")
SANITIZED = os.environ.get("ESSAIM_SANITIZED") == "1"
pytestmark = pytest.mark.skipif(not ESSAIM, reason="set ESSAIM to the essaim binary")
TIMEOUT = 120


def limit_address_space():
    if not SANITIZED:
        four_gib = 4 << 30
        resource.setrlimit(resource.RLIMIT_AS, (four_gib, four_gib))


ARENA = """<?xml version="1.0" ?>
<argos-configuration>
  <framework>
    <system threads="0" {system}/>
    <experiment length="{length}" ticks_per_second="10" random_seed="1" />
  </framework>
  <controllers>
    <lua_controller id="ctrl">
      <actuators>
        <differential_steering implementation="default" />
        <range_and_bearing implementation="default" />
      </actuators>
      <sensors>
        <positioning implementation="default" />
        <range_and_bearing implementation="medium" medium="rab" />
      </sensors>
      <params script="ctrl.lua" />
    </lua_controller>
  </controllers>
  <arena size="4, 4, 1" center="0, 0, 0.5">
    {entities}
    <foot-bot id="fb0"><body position="0,0,0" orientation="0,0,0"/><controller config="ctrl"/></foot-bot>
    <foot-bot id="fb1"><body position="1,0,0" orientation="0,0,0"/><controller config="ctrl"/></foot-bot>
  </arena>
  <physics_engines><dynamics2d id="dyn2d" /></physics_engines>
  <media><range_and_bearing id="rab" /></media>
  {loop}
</argos-configuration>
"""

IDLE = "function init() end\nfunction step() robot.wheels.set_velocity(1, 1) end\n"


def arena(folder, controller=IDLE, loop=None, entities="", system="", length=2):
    """Writes folder/test.argos with two robots running `controller`; returns its path."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "ctrl.lua").write_text(controller)
    loop_xml = ""
    if loop is not None:
        (folder / "loop.lua").write_text(loop)
        loop_xml = '<loop_functions script="loop.lua" />'
    path = folder / "test.argos"
    path.write_text(ARENA.format(system=system, length=length, entities=entities, loop=loop_xml))
    return path


def essaim(*args, cwd=None, timeout=TIMEOUT, **kw):
    return subprocess.run([ESSAIM, *map(str, args)], capture_output=True, text=True, timeout=timeout, cwd=cwd,
                          preexec_fn=limit_address_space, **kw)


def run(path, out, *extra, **kw):
    return essaim("run", path, "--out", out, "--quiet", *extra, **kw)


def summary(out):
    return json.loads((Path(out) / "summary.json").read_text())


def no_temporary_files(out):
    return [p.name for p in Path(out).iterdir() if ".tmp." in p.name] == []


# 1. A 10 km box: refused before anything is allocated, from the file and from add_entity.
def test_case01_huge_entities_are_refused_before_allocating(tmp_path):
    box = ('<box id="wall" size="10000,10000,0.5" movable="false">'
           '<body position="0,6000,0" orientation="0,0,0"/></box>')
    p = run(arena(tmp_path / "xml", entities=box), tmp_path / "o1")
    assert p.returncode == 2, p.stderr
    assert "test.argos:" in p.stderr and "box" in p.stderr
    assert "size 10000 m is over the limit of 1000 m (<system max_entity_size>)" in p.stderr
    loop = ('function init()\n'
            '  experiment.add_entity("box", {id = "w", position = {0, 6000, 0}, size = {10000, 10000, 0.5}})\n'
            'end\n')
    p = run(arena(tmp_path / "lua", loop=loop), tmp_path / "o2")
    assert p.returncode == 1, p.stderr
    assert "loop.lua:2: add_entity: size 10000 m is over the limit" in p.stderr
    assert summary(tmp_path / "o2")["status"] == "failed"
    # The limit can be raised: a 2 km wall then loads (its fixtures are capped, not 10^6).
    wall = ('<box id="wall" size="2000,2000,0.5" movable="false">'
            '<body position="0,1003,0" orientation="0,0,0"/></box>')
    p = run(arena(tmp_path / "raised", entities=wall, system='max_entity_size="3000"', length=1), tmp_path / "o3")
    assert p.returncode == 0, p.stderr
    # Too many entities, and an arena too large.
    many = ('<distribute><position method="uniform" min="-2,-2,0" max="2,2,0"/>'
            '<orientation method="constant" values="0,0,0"/>'
            '<entity quantity="100000000" max_trials="1"><cylinder id="c" radius="0.01" height="0.1" movable="false"/>'
            '</entity>'
            '</distribute>')
    p = run(arena(tmp_path / "many", entities=many), tmp_path / "o4")
    assert p.returncode == 2, p.stderr
    assert "100000002 entities (2 foot-bots) would need about 381.5 GiB, over half of the " in p.stderr, p.stderr
    assert '<system max_entities="N"/> allows N entities' in p.stderr, p.stderr
    big = arena(tmp_path / "big")
    big.write_text(big.read_text().replace('size="4, 4, 1"', 'size="100000, 4, 1"'))
    p = run(big, tmp_path / "o5")
    assert p.returncode == 2 and "over the limit of 10000 m per side" in p.stderr, p.stderr


def write_png(path, width, height):
    """A black 1-bit PNG: a 30000 x 30000 image in about 110 kB that decodes to 3.6 GB."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    z = zlib.compressobj(9)
    row = b"\0" * ((width + 7) // 8 + 1)
    data = b"".join(z.compress(row) for _ in range(height)) + z.flush()
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 1, 0, 0, 0, 0)) +
                chunk(b"IDAT", data) + chunk(b"IEND", b""))


# 2. A decompression bomb as the floor image: refused from its header, rc 2.
def test_case02_floor_image_bomb_is_refused_from_its_header(tmp_path):
    png = tmp_path / "bomb.png"
    write_png(png, 30000, 30000)
    floor = f'<floor id="floor" source="image" path="{png}" />'
    p = run(arena(tmp_path / "a", entities=floor), tmp_path / "out")
    assert p.returncode == 2, p.stderr
    assert "30000 x 30000 pixels is over the limit of 67108864 pixels (<system max_floor_pixels>)" in p.stderr
    assert "test.argos:" in p.stderr and "floor" in p.stderr
    assert summary(tmp_path / "out")["status"] == "failed"


LOOPS = {
    "gc": "function step()\n  setmetatable({}, {__gc = function() while true do end end})\n  collectgarbage()\nend\n",
    "xpcall": ("function step()\n  xpcall(function() error('x') end,\n"
               "         function(m) while true do end end)\nend\n"),
    "sethook": "function step()\n  while true do debug.sethook() end\nend\n",
}


# 3. Endless loops where the hook used not to reach: finalizers, message handlers, sethook.
@pytest.mark.parametrize("kind", sorted(LOOPS))
@pytest.mark.parametrize("sandbox", [False, True])
def test_case03_watchdog_cannot_be_escaped(tmp_path, kind, sandbox):
    if kind == "sethook" and sandbox:
        pytest.skip("the sandbox has no debug library")
    out = tmp_path / "out"
    extra = ["--sandbox"] if sandbox else []
    # The instruction budget is what stops them; the wall-clock limit is a backstop set far
    # above the budget's time, so that a busy machine does not reach it first (it did at 2 s).
    p = run(arena(tmp_path, LOOPS[kind]), out, "--lua-budget", "1e7", "--lua-seconds", "25", "--record", *extra)
    assert p.returncode == 0, p.stderr
    s = summary(out)
    assert s["status"] == "controller_error" and s["ticks"] == 20
    messages = {e["robot"]: e["message"] for e in s["controller_errors"]}
    assert set(messages) == {"fb0", "fb1"}
    expected = {
        "gc": "ctrl.lua:2: setmetatable: a __gc finalizer is refused",
        "xpcall": "instruction budget exceeded (10000000 instructions per call",
        "sethook": "ctrl.lua:2: debug.sethook is not available",
    }[kind]
    assert expected in messages["fb0"]
    assert (out / "recording.bin").is_file() and no_temporary_files(out)


# 3 (the last resort): a call stuck inside one C function still leaves a summary naming the
# last line seen, and a closed recording.
def test_case03_stuck_in_c_leaves_summary_and_recording(tmp_path):
    # Line 3 runs 2 to 3 s of wall-clock time (os.time, not os.clock's CPU time: on a busy
    # machine 1.2 s of CPU took longer than the limit), so the watchdog sees that line before
    # line 4 sticks in C; both well under --lua-seconds (and no instruction budget to reach).
    ctrl = ("function step()\n  local t = os.time()\n  while os.time() - t < 3 do end\n"
            "  string.find(string.rep('a', 40), string.rep('a*', 40) .. 'b')\nend\n")
    out = tmp_path / "out"
    p = run(arena(tmp_path, ctrl), out, "--lua-budget", "0", "--lua-seconds", "8", "--record")
    assert p.returncode == 1, p.stderr
    s = summary(out)
    assert s["status"] == "failed"
    assert "stuck for" in s["failure"] and "inside a C function called from Lua (last at " in s["failure"]
    assert "ctrl.lua:3)" in s["failure"]
    assert (out / "recording.bin").is_file() and no_temporary_files(out)
    assert essaim("replay", out, "-o", tmp_path / "r.html").returncode == 0


# 4. os.exit ends the run as an error, with its outputs; essaim chooses the exit code.
@pytest.mark.parametrize("call", ["os.exit(7)", "os.exit(true, true)", "pcall(os.exit, 0)"])
def test_case04_os_exit_stops_the_run_cleanly(tmp_path, call):
    out = tmp_path / "out"
    ctrl = f"function step()\n  if robot.id == 'fb1' then\n    {call}\n  end\nend\n"
    p = run(arena(tmp_path, ctrl), out, "--record")
    assert p.returncode == 1, p.stderr
    s = summary(out)
    # As with --strict: a controller error ended the run, and the failure names it.
    assert s["status"] == "controller_error" and s["finished_by"] == "error" and s["ticks"] == 1
    assert "robot fb1: os.exit called at " in s["failure"] and "ctrl.lua:3 (in step)" in s["failure"]
    assert (out / "recording.bin").is_file() and no_temporary_files(out)
    loop = "function post_step()\n  os.exit(3)\nend\n"
    p = run(arena(tmp_path / "lf", loop=loop), tmp_path / "o2")
    assert p.returncode == 1 and "os.exit called at" in summary(tmp_path / "o2")["failure"], p.stderr


# 5. The sandbox's require stays inside the arena's folder, whatever package.path says.
def test_case05_sandbox_require_stays_in_the_arena_folder(tmp_path):
    secret = tmp_path / "outside"
    secret.mkdir()
    (secret / "secret.lua").write_text("return 1 SECRET_7f3a9\n")  # a syntax error quoting it
    (tmp_path / "a" / "lib").mkdir(parents=True)
    (tmp_path / "a" / "lib" / "helper.lua").write_text("return {x = 42}\n")
    ctrl = (f'package.path = "{secret}/?.lua;" .. package.path\n'
            'local h = require("lib.helper")\n'
            'function step()\n  log(h.x)\n  require("secret")\nend\n')
    loop = (f'package.path = "{secret}/?.lua;" .. package.path\n'
            'function post_step()\n  require("secret")\nend\n')
    out = tmp_path / "out"
    p = run(arena(tmp_path / "a", ctrl), out, "--sandbox", "--ticks", "2")
    assert p.returncode == 0, p.stderr
    assert "SECRET" not in p.stderr + p.stdout + (out / "summary.json").read_text()
    messages = [e["message"] for e in summary(out)["controller_errors"]]
    assert messages and all("module 'secret' not found" in m for m in messages)
    assert "42" in p.stdout  # a module inside the arena's folder still loads
    (tmp_path / "a" / "bad.lua").write_text("return 1 oops\n")
    (tmp_path / "a" / "ctrl.lua").write_text("function step() require('bad') end\n")
    p = run(tmp_path / "a" / "test.argos", tmp_path / "o3", "--sandbox", "--ticks", "1")
    messages = [e["message"] for e in summary(tmp_path / "o3")["controller_errors"]]
    assert messages and all("error loading module 'bad' from file" in m and "oops" in m for m in messages), messages
    p = run(arena(tmp_path / "b", loop=loop), tmp_path / "o2", "--sandbox", "--ticks", "2")
    assert p.returncode == 1 and "module 'secret' not found" in p.stderr
    assert "SECRET" not in p.stderr + (tmp_path / "o2" / "summary.json").read_text()


# 6. A FIFO in --log-dir is refused at once (no blocking open).
def test_case06_special_files_in_log_dir_are_refused(tmp_path):
    logs = tmp_path / "logs"
    logs.mkdir()
    os.mkfifo(logs / "fb0.log")
    p = run(arena(tmp_path / "a", 'function step() log("hi") end\n'), tmp_path / "out", "--log-dir", logs,
            timeout=30)
    assert p.returncode == 2, p.stderr
    assert "fb0.log" in p.stderr and "FIFO" in p.stderr


def start(path, out, *extra):
    return subprocess.Popen([ESSAIM, "run", str(path), "--out", str(out), "--quiet", *map(str, extra)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=limit_address_space)


def wait_for(path, proc, seconds=60):
    deadline = time.monotonic() + seconds
    while not path.exists():
        assert proc.poll() is None, proc.communicate()
        assert time.monotonic() < deadline, f"{path} never appeared"
        time.sleep(0.05)


# 7. SIGTERM while a controller is stuck in init(): interrupted, with a summary.
def test_case07_signal_during_a_stuck_init_writes_the_summary(tmp_path):
    marker = tmp_path / "in_init"
    ctrl = (f'function init()\n  io.open("{marker}", "w"):close()\n  while true do end\nend\n'
            'function step() end\n')
    out = tmp_path / "out"
    proc = start(arena(tmp_path, ctrl), out, "--lua-budget", "0", "--record")
    wait_for(marker, proc)
    time.sleep(0.3)
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 143, err
    s = summary(out)
    assert s["status"] == "interrupted"
    assert any("ctrl.lua:3: interrupted by a signal" in e["message"] for e in s["controller_errors"]), s
    assert no_temporary_files(out)


# 8. Two runs into one --out: the second is refused, naming the folder and the owner.
def test_case08_out_folder_is_locked_by_its_run(tmp_path):
    release = tmp_path / "release"
    started = tmp_path / "started"
    ctrl = (f'function init() io.open("{started}", "w"):close() end\n'
            f'function step()\n  while not io.open("{release}") do end\nend\n')
    out = tmp_path / "out"
    first = start(arena(tmp_path / "a", ctrl), out, "--lua-budget", "0", "--ticks", "1")
    wait_for(started, first)
    second = run(arena(tmp_path / "b"), out, "--ticks", "3")
    release.touch()
    _, err = first.communicate(timeout=60)
    assert first.returncode == 0, err
    assert second.returncode == 2, second.stderr
    assert str(out) in second.stderr and f"pid {first.pid}" in second.stderr
    assert summary(out)["ticks"] == 1 and not (out / "previous").exists()
    p = run(arena(tmp_path / "b"), out, "--ticks", "3")  # the lock went with its run
    assert p.returncode == 0 and summary(out)["ticks"] == 3, p.stderr


# 9. Earlier runs are kept as numbered generations: previous/, previous-2/, ...
def test_case09_earlier_runs_are_never_lost(tmp_path):
    path = arena(tmp_path)
    out = tmp_path / "out"
    for seed in (1, 2, 3, 4):
        p = run(path, out, "--seed", seed, "--ticks", "2")
        assert p.returncode == 0, p.stderr
    assert summary(out)["seed"] == 4
    assert summary(out / "previous")["seed"] == 3
    assert summary(out / "previous-2")["seed"] == 2
    assert summary(out / "previous-3")["seed"] == 1


# 10. The Python module refuses what the CLI refuses, before creating anything.
def test_case10_python_module_refusals(tmp_path):
    script = f"""
import os, sys, essaim
path = {str(arena(tmp_path))!r}
out = {str(tmp_path / 'x')!r}
for kw in (dict(threads=100000), dict(threads=0), dict(threads=-1)):
    try:
        essaim.Simulation(path, **kw)
        sys.exit("threads accepted: %r" % kw)
    except ValueError as e:
        assert "threads" in str(e), e
for kw in (dict(out=out + "\\0y"),):
    try:
        essaim.Simulation(path, **kw)
        sys.exit("NUL accepted: %r" % kw)
    except ValueError as e:
        assert "NUL" in str(e), e
try:
    essaim.Simulation(path + "\\0.argos")
    sys.exit("NUL accepted in the path")
except ValueError as e:
    assert "NUL" in str(e), e
assert not os.path.exists(out), "created before refusing"
sim = essaim.Simulation(path, out=out)
sim.step(2)
sim.finish()
for call in (lambda: sim.step(1), lambda: sim.run(), lambda: sim.finish()):
    try:
        call()
        sys.exit("a call after finish() went through")
    except essaim.Error as e:
        assert "finish() was called" in str(e), e
print("ok")
"""
    env = dict(os.environ)
    if os.environ.get("ESSAIM_ASAN_PRELOAD"):  # the module is built with ASan, Python is not
        env.update(LD_PRELOAD=os.environ["ESSAIM_ASAN_PRELOAD"], ASAN_OPTIONS="detect_leaks=0")
    p = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=TIMEOUT,
                       preexec_fn=limit_address_space, env=env)
    assert p.returncode == 0 and p.stdout.strip().endswith("ok"), p.stdout + p.stderr


# 11. add_entity checks overlap and ranges as the loader does.
@pytest.mark.parametrize("spec,message", [
    ('"cylinder", {position = {0, 0, 0}, radius = 0.2, height = 0.5}', "it would overlap foot-bot 'fb0'"),
    ('"box", {position = {1.5, 1.5, -50}, size = {0.2, 0.2, 0.2}}', "z = -50 puts it below the floor"),
])
def test_case11_add_entity_checks_like_the_loader(tmp_path, spec, message):
    loop = f"function init()\n  experiment.add_entity({spec})\nend\n"
    p = run(arena(tmp_path, loop=loop), tmp_path / "out")
    assert p.returncode == 1, p.stderr
    assert f"loop.lua:2: add_entity: {message}" in p.stderr
    # And the loader refuses the same box from the file.
    if "box" in spec:
        box = ('<box id="b" size="0.2,0.2,0.2" movable="false">'
               '<body position="1.5,1.5,-50" orientation="0,0,0"/></box>')
        p = run(arena(tmp_path / "xml", entities=box), tmp_path / "o2")
        assert p.returncode == 2 and message in p.stderr, p.stderr


# 12. set_data refuses non-finite and out-of-range values, naming the value.
@pytest.mark.parametrize("call,shown", [
    ("set_data(1, 1e300)", "value 1e+300 is out of range"),
    ("set_data(1, -2^40)", "value -1.09951e+12 is out of range"),
    ("set_data({1, 2, 3, 4, 5, 6, 7, 8, 9, 2^31})", "element #10 2.14748e+09 is out of range"),
    ("set_data(1, 0/0)", "argument #2 is"),
])
def test_case12_set_data_refuses_out_of_range_values(tmp_path, call, shown):
    ctrl = f"function step()\n  robot.range_and_bearing.{call}\nend\n"
    p = run(arena(tmp_path, ctrl), tmp_path / "out", "--ticks", "2")
    assert p.returncode == 0, p.stderr
    messages = [e["message"] for e in summary(tmp_path / "out")["controller_errors"]]
    assert len(messages) == 2 and all("ctrl.lua:2:" in m and shown in m for m in messages), messages


def test_case12_bytes_still_wrap_as_in_argos(tmp_path):
    ctrl = ("function step()\n  robot.range_and_bearing.set_data(1, -1)\n"
            "  robot.range_and_bearing.set_data(2, 300)\n"
            "  for _, m in ipairs(robot.range_and_bearing) do log('got ', m.data[1], ' ', m.data[2]) end\nend\n")
    p = run(arena(tmp_path, ctrl), tmp_path / "out", "--ticks", "3")
    assert p.returncode == 0 and summary(tmp_path / "out")["status"] == "ok", p.stderr
    assert "got 255 44" in p.stdout


# 13. A device as the floor image is named as such.
def test_case13_special_file_as_floor_image_is_named(tmp_path):
    floor = '<floor id="floor" source="image" path="/dev/zero" />'
    p = run(arena(tmp_path, entities=floor), tmp_path / "out")
    assert p.returncode == 2, p.stderr
    assert "floor image '/dev/zero': is a character device, not a PNG file" in p.stderr


# 14. The memory limit names the script's line.
def test_case14_memory_limit_names_the_line(tmp_path):
    ctrl = "local t = {}\nfunction step()\n  for i = 1, 1e9 do\n    t[i] = {i}\n  end\nend\n"
    p = run(arena(tmp_path, ctrl), tmp_path / "out", "--lua-memory", "8", "--ticks", "2")
    assert p.returncode == 0, p.stderr
    messages = [e["message"] for e in summary(tmp_path / "out")["controller_errors"]]
    assert messages and all("ctrl.lua:4: memory limit exceeded (8 MiB per Lua state" in m for m in messages), messages
