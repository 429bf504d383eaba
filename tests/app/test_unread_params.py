"""A parameter given in the XML or by --set that no script reads is reported, with the
closest key that was read; --strict makes it a failure. robot.params still behaves as the
table ARGoS gives (indexing, pairs, strings)."""
import json

from clitest import ROOT, argos, essaim, need_essaim, run, write

pytestmark = need_essaim


def test_misspelled_set_on_the_foraging_arena_is_named_with_a_suggestion(tmp_path):
    args = ["run", ROOT / "arenas/foraging.argos", "--ticks", "3", "--out", tmp_path / "o",
            "--set", "controllers.foraging.params.EPSILONGRED=0.3"]
    r = essaim(*args, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    line = next(l for l in r.stderr.splitlines() if "EPSILONGRED" in l)
    assert line.startswith(str(ROOT / "arenas/foraging.argos") + ":12: <lua_controller>: warning: ")
    assert "parameter 'EPSILONGRED' (--set controllers.foraging.params.EPSILONGRED=0.3) is never read" in line
    assert line.endswith("did you mean 'EPSILONGREED'?")
    s = json.loads((tmp_path / "o/summary.json").read_text())
    assert s["unread_params"] == [{"path": "controllers.foraging.params.EPSILONGRED", "did_you_mean": "EPSILONGREED"}]
    strict = essaim(*args, "--strict", cwd=tmp_path)
    assert strict.returncode == 1
    assert "error: parameter 'EPSILONGRED'" in strict.stderr


def test_quiet_keeps_warnings_and_drops_only_progress_and_summary(tmp_path):
    # A sweep runs with -q: it must still hear of a typo and of an unknown attribute.
    write(tmp_path, {"x.argos": argos(params='gain="1"').replace('<experiment ', '<experiment colour="red" '),
                     "c.lua": "function step() end\n"})
    r = essaim("run", "x.argos", "-q", "--out", "o", "--set", "controllers.c.params.gian=2", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert "warning: parameter 'gian' (--set controllers.c.params.gian=2) is never read" in r.stderr, r.stderr
    assert "warning: parameter 'gain' is never read" in r.stderr, r.stderr
    assert "<experiment>: warning: unknown attribute 'colour'" in r.stderr, r.stderr
    assert r.stdout == "", r.stdout  # no summary line


def test_the_shipped_foraging_arena_reads_every_parameter(tmp_path):
    r = essaim("run", ROOT / "arenas/foraging.argos", "--ticks", "3", "--strict", "--out", tmp_path / "o",
               cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert "never read" not in r.stderr


PARAMS_USER = """
function init()
  local p = robot.params
  assert(type(p) == "table" and p.speed == "12" and type(p.speed) == "string")
  local seen = {}
  for k, v in pairs(p) do seen[#seen + 1] = k .. "=" .. v end
  table.sort(seen)
  assert(table.concat(seen, ",") == "late=1,script=c.lua,speed=12,unused=3", table.concat(seen, ","))
  p.added = "x"
  assert(p.added == "x")
end
function step() robot.wheels.set_velocity(tonumber(robot.params.speed), 0) end
"""


def test_params_behave_as_a_table_and_reads_in_pairs_count(tmp_path):
    # pairs() visits every key: all count as read.
    write(tmp_path, {"x.argos": argos(params='speed="12" unused="3" late="1"'), "c.lua": PARAMS_USER})
    r, s = run(tmp_path, "x.argos", "--strict")
    assert r.returncode == 0, r.stderr
    assert s["unread_params"] == [] and s["controller_errors"] == []


def test_a_key_read_only_in_step_counts_and_a_loop_functions_attribute_too(tmp_path):
    ctrl = "function init() end\nfunction step() local _ = robot.params.gain end\n"
    loop = "function init() local _ = experiment.params.every end\n"
    write(tmp_path, {"x.argos": argos(params='gain="1" gian="2"', length=2,
                                      loop='<loop_functions script="loop.lua" every="3" evrey="4" />'),
                     "c.lua": ctrl, "loop.lua": loop})
    r, s = run(tmp_path, "x.argos")
    assert r.returncode == 0, r.stderr
    r = essaim("run", "x.argos", "--out", "out", cwd=tmp_path)  # not --quiet: warnings printed
    assert s["unread_params"] == [{"path": "controllers.c.params.gian", "did_you_mean": "gain"},
                                  {"path": "loop_functions.evrey", "did_you_mean": "every"}]
    assert "x.argos:13: <loop_functions>: warning: parameter 'evrey' is never read by " in r.stderr
    assert "loop.lua; did you mean 'every'?" in r.stderr
