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


# A run with no end: a misspelt length leaves none, and nothing says the run will go on forever.
LENGTHLESS = argos().replace('length="1"', 'lenght="6"')
STEP = "function init() end\nfunction step() end\n"


def test_a_misspelt_length_warns_that_the_run_has_no_end(tmp_path):
    write(tmp_path, {"x.argos": LENGTHLESS, "c.lua": STEP})
    r = check(tmp_path)
    assert r.returncode == 0, r.stderr  # a warning, not a failure
    assert ("x.argos:4: <experiment>: warning: unknown attribute 'lenght' (essaim does not read it); "
            "did you mean 'length'?; with no length, the run has no end (until Ctrl-C; --ticks N sets one)") \
        in r.stderr
    assert ("x.argos: warning: the run has no end: no length in <experiment> and no --ticks, and no loop "
            "functions: it runs until Ctrl-C") in r.stderr
    assert "x.argos: ok (3 robots, 0 obstacles, no length;" in r.stdout
    # `run` prints the same warning about the attribute before it starts.
    r = essaim("run", "x.argos", "-q", "--ticks", "2", "--out", "o", cwd=tmp_path)
    assert r.returncode == 0 and "did you mean 'length'?" in r.stderr
    # --ticks gives the run an end: neither warning speaks of one.
    r = check(tmp_path, "--ticks", "5")
    assert r.returncode == 0 and "no end" not in r.stderr and "5 ticks;" in r.stdout


def test_no_end_unless_the_loop_functions_can_end_it(tmp_path):
    loop = '<loop_functions script="loop.lua" />'
    write(tmp_path, {"x.argos": LENGTHLESS.replace("<arena ", loop + "\n  <arena "), "c.lua": STEP,
                     "loop.lua": "function post_step() end\n"})
    r = check(tmp_path)
    assert r.returncode == 0, r.stderr
    assert "did you mean 'length'?; with no length, the run has no end unless the loop functions end it" \
        in r.stderr
    assert ("x.argos: warning: the run has no end: no length in <experiment> and no --ticks, and the loop "
            "functions define no is_experiment_finished(): it runs until Ctrl-C") in r.stderr
    # Loop functions that can end it: no warning from check (the attribute's still says why).
    (tmp_path / "loop.lua").write_text("function is_experiment_finished() return false end\n")
    r = check(tmp_path)
    assert r.returncode == 0 and "warning: the run has no end" not in r.stderr, r.stderr
    # -q: errors only.
    (tmp_path / "loop.lua").write_text("function post_step() end\n")
    assert "warning: the run has no end" not in check(tmp_path, "-q").stderr


def test_a_deliberate_length_of_0_warns_too(tmp_path):
    write(tmp_path, {"x.argos": argos(length=0), "c.lua": STEP})
    r = check(tmp_path)
    assert r.returncode == 0, r.stderr
    assert "x.argos: warning: the run has no end" in r.stderr and "unknown attribute" not in r.stderr
