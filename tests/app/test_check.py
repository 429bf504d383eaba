"""`essaim check` loads every script, runs init() and a few ticks on a sample of the robots,
and lists every problem with file:line (exit 2); `essaim run` of a controller without step()
fails, naming the file."""
from clitest import ROOT, argos, essaim, need_essaim, run, write

pytestmark = need_essaim


def check(folder, *args):
    return essaim("check", "x.argos", *args, cwd=folder)


def test_an_init_error_is_reported_with_its_line(tmp_path):
    write(tmp_path, {"x.argos": argos(), "c.lua": "function init()\n  local x = nil + 1\nend\nfunction step() end\n"})
    r = check(tmp_path)
    assert r.returncode == 2, r.stdout + r.stderr
    assert "robot fb0: c.lua:2: attempt to perform arithmetic on a nil value" in r.stderr
    assert "(the same error in 2 more robots: fb1, fb2)" in r.stderr


def test_a_step_error_in_the_first_ticks_is_reported(tmp_path):
    write(tmp_path, {"x.argos": argos(length=100),
                     "c.lua": "function init() end\nfunction step()\n  if robot.id == 'fb1' then error('boom') end\nend\n"})
    r = check(tmp_path)
    assert r.returncode == 2
    assert "robot fb1: c.lua:3: boom" in r.stderr


def test_a_missing_step_fails_check_and_run(tmp_path):
    write(tmp_path, {"x.argos": argos(), "c.lua": "function init() end\n"})
    r = check(tmp_path)
    assert r.returncode == 2
    assert "robot fb0: c.lua: no global function 'step' after init() (nor in 2 more robots)" in r.stderr
    r, s = run(tmp_path, "x.argos")
    assert r.returncode == 1
    assert "c.lua: no global function 'step'" in r.stderr
    assert s["status"] == "failed" and "no global function 'step'" in s["failure"]


def test_an_unread_parameter_is_a_problem_for_check(tmp_path):
    write(tmp_path, {"x.argos": argos(params='speed="1"'),
                     "c.lua": "function init() end\nfunction step() local _ = robot.params.sped end\n"})
    r = check(tmp_path)
    assert r.returncode == 2
    assert "x.argos:7: <lua_controller>: error: parameter 'speed' is never read by c.lua; did you mean 'sped'?" \
        in r.stderr


def test_a_good_file_passes_and_says_what_ran(tmp_path):
    write(tmp_path, {"x.argos": argos(robots=3), "c.lua": "function init() end\nfunction step() end\n"})
    r = check(tmp_path)
    assert r.returncode == 0, r.stderr
    assert "x.argos: ok (3 robots" in r.stdout and "init() and 10 ticks run on 3 robots" in r.stdout


def test_the_shipped_foraging_arena_passes_on_a_sample(tmp_path):
    r = essaim("check", ROOT / "arenas/foraging.argos", "--set", "arena.distribute.entity.quantity=60")
    assert r.returncode == 0, r.stderr
    assert "init() and 10 ticks run on 20 robots" in r.stdout
