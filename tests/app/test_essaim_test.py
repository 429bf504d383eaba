"""`essaim test SPEC.toml` (docs/testing.md): expectations over seeds, the table and its exit
code, JUnit XML, spec errors, failed runs and golden runs."""
import xml.etree.ElementTree as ET
from pathlib import Path

from clitest import argos, check_junit_shape, essaim, need_essaim, write

pytestmark = need_essaim

# Each run's metrics are its seed, so every statistic over seeds 1..10 is known exactly.
LOOP = """
function post_experiment()
  return {seed = experiment.seed, even = experiment.seed % 2 == 0, odd_only = experiment.seed % 2 == 1 or nil}
end
"""
CONTROLLER = "function init() end\nfunction step() robot.wheels.set_velocity(5, 5) end\n"


def project(folder: Path, spec: str, controller=CONTROLLER):
    write(folder, {"x.argos": argos(loop='<loop_functions script="loop.lua"/>', length=2),
                   "c.lua": controller, "loop.lua": LOOP, "x.test.toml": spec})


def spec_text(expect, extra=""):
    lines = "".join(f'  "{e}",\n' for e in expect)
    return f'experiment = "x.argos"\nseeds = 10\nticks = 5\n{extra}\nexpect = [\n{lines}]\n'


def rows(stdout):
    """expectation -> (value, verdict, failed seeds) from the printed table."""
    table = {}
    for line in stdout.splitlines()[2:]:
        for verdict in ("  pass", "  FAIL"):
            if verdict + " " in line:
                left, right = line.split(verdict + " ", 1)
                expectation, value = left.rstrip().rsplit("  ", 1)
                table[expectation.strip()] = (value.strip(), verdict.strip(), right.strip())
    return table


def test_statistics_over_seeds_and_the_seeds_that_fail(tmp_path):
    expect = ["mean seed == 5.5", "median seed == 5.5", "min seed == 1", "max seed == 10",
              "quantile(0.1) seed > 1.89", "quantile(0.1) seed < 1.91", "fraction(seed <= 8) >= 0.8",
              "mean even == 0.5", "each errors == 0", "each ticks == 5",
              "fraction(seed <= 8) > 0.8", "each seed < 10", "mean odd_only > 0"]
    project(tmp_path, spec_text(expect))
    r = essaim("test", "x.test.toml", "-j", "3", "--junit", "out.xml", cwd=tmp_path)
    assert r.returncode == 1, r.stdout + r.stderr
    table = rows(r.stdout)
    for e in expect[:10]:
        assert table[e][1] == "pass", (e, table[e])
    assert table["every run finishes (exit 0)"][1] == "pass"
    assert table["fraction(seed <= 8) > 0.8"] == ("0.8 (8/10)", "FAIL", "9, 10")
    assert table["each seed < 10"] == ("9/10 runs", "FAIL", "10")
    assert table["mean odd_only > 0"] == ("'odd_only' missing in 5 run(s)", "FAIL", "2, 4, 6, 8, 10")
    assert "x.test.toml:18: seed 2: metrics.json has no 'odd_only'" in r.stdout  # a value only some runs lack
    assert "3 expectations" not in r.stdout and "11 of 14 expectations hold" in r.stdout

    root = ET.parse(tmp_path / "out.xml").getroot()
    check_junit_shape(root)
    suite = root.find("testsuite")
    cases = suite.findall("testcase")
    assert suite.get("name") == "x.test" and int(suite.get("tests")) == len(cases) == 14
    failed = [c for c in cases if c.find("failure") is not None]
    assert int(suite.get("failures")) == len(failed) == 3
    assert {c.get("name") for c in failed} == {"fraction(seed <= 8) > 0.8", "each seed < 10", "mean odd_only > 0"}
    assert "seeds 9, 10" in [c for c in failed if c.get("name").startswith("fraction")][0].find("failure").get("message")


def test_every_expectation_holding_exits_0_and_parallel_runs_agree(tmp_path):
    project(tmp_path, spec_text(["each errors == 0", "mean seed == 5.5"]))
    one = essaim("test", "x.test.toml", "-j", "1", "--out", "one", cwd=tmp_path)
    four = essaim("test", "x.test.toml", "-j", "4", "--out", "four", cwd=tmp_path)
    assert one.returncode == four.returncode == 0, one.stdout + one.stderr
    for seed in range(1, 11):
        assert (tmp_path / "one" / f"seed-{seed}" / "metrics.json").read_text() == \
            (tmp_path / "four" / f"seed-{seed}" / "metrics.json").read_text()


def test_a_spec_that_cannot_be_read_is_exit_2_with_file_and_line(tmp_path):
    project(tmp_path, 'experiment = "x.argos"\nseed = 3\nexpect = [\n  "meen seed > 1",\n  "each seed >> 1",\n]\n')
    r = essaim("test", "x.test.toml", cwd=tmp_path)
    assert r.returncode == 2
    assert "x.test.toml:2: unknown key 'seed'; did you mean 'seeds'?" in r.stderr
    project(tmp_path, spec_text(["meen seed > 1", "each seed >> 1", "quantile seed > 1"]))
    r = essaim("test", "x.test.toml", cwd=tmp_path)
    assert r.returncode == 2
    assert "x.test.toml:6: expect \"meen seed > 1\"" in r.stderr and "did you mean 'mean'?" in r.stderr
    assert "x.test.toml:7:" in r.stderr and "unknown comparison '>>'" in r.stderr
    assert "x.test.toml:8:" in r.stderr and "quantile(0.1) VALUE OP N" in r.stderr
    write(tmp_path, {"x.test.toml": 'experiment = "missing.argos"\nexpect = ["each errors == 0"]\n'})
    r = essaim("test", "x.test.toml", cwd=tmp_path)
    assert r.returncode == 2 and "missing.argos does not exist" in r.stderr
    write(tmp_path, {"x.test.toml": 'experiment = "x.argos"\nseeds = [1, 2, 1]\ngolden = "g.json"\ngolden_seed = 5\n'})
    r = essaim("test", "x.test.toml", cwd=tmp_path)
    assert r.returncode == 2 and "x.test.toml:2: seeds: a seed is listed twice" in r.stderr
    assert "x.test.toml:4: golden_seed 5 is not one of the seeds" in r.stderr
    write(tmp_path, {"x.test.toml": 'experiment = "x.argos"\nticks = [\n'})
    r = essaim("test", "x.test.toml", cwd=tmp_path)
    assert r.returncode == 2 and r.stderr.startswith("x.test.toml:")


def test_runs_that_fail_are_counted_and_the_test_goes_on(tmp_path):
    broken = CONTROLLER + "if robot.id == 'fb1' then error('boom') end\n"  # every run: a load error
    project(tmp_path, spec_text(["each errors == 0"]) + '[set]\n"framework.experiment.length" = 2\n', broken)
    r = essaim("test", "x.test.toml", "-j", "2", cwd=tmp_path)
    assert r.returncode == 1, r.stderr
    value, verdict, seeds = rows(r.stdout)["every run finishes (exit 0)"]
    assert (value, verdict, seeds) == ("0/10 runs", "FAIL", "1, 2, 3, 4, 5, 6, 7, 8, 9, 10")
    assert "seed 1: exit 2: " in r.stdout and "boom" in r.stdout and "seed-1/run.log" in r.stdout
    step_error = CONTROLLER.replace("set_velocity(5, 5)", "set_velocity(5, 5) if robot.id == 'fb2' then error('stepped on') end")
    project(tmp_path, spec_text(["each errors == 0"]), step_error)
    r = essaim("test", "x.test.toml", "-j", "2", cwd=tmp_path)
    assert r.returncode == 1
    assert rows(r.stdout)["each errors == 0"] == ("0/10 runs", "FAIL", "1, 2, 3, 4, 5, 6, 7, 8, 9, 10")
    assert "seed(s) 1, 2, 3, 4, 5, 6, 7, 8, 9, 10: robot fb2:" in r.stdout and "stepped on" in r.stdout


def test_golden_run_fails_on_a_difference_and_update_rewrites_it(tmp_path):
    spec = spec_text([], extra='golden = "x.golden.json"\nseeds = [4]\n').replace("seeds = 10\n", "")
    project(tmp_path, spec)
    r = essaim("test", "x.test.toml", cwd=tmp_path)
    assert r.returncode == 1 and "no golden file (essaim test --update writes it)" in r.stdout
    r = essaim("test", "x.test.toml", "--update", cwd=tmp_path)
    assert r.returncode == 0 and "written (new)" in r.stdout
    assert '"seed": 4' in (tmp_path / "x.golden.json").read_text()
    assert essaim("test", "x.test.toml", cwd=tmp_path).returncode == 0
    project(tmp_path, spec, CONTROLLER.replace("(5, 5)", "(5, 6)"))  # the robots now turn
    r = essaim("test", "x.test.toml", cwd=tmp_path)
    assert r.returncode == 1 and "difference(s)" in r.stdout
    assert "    recording: \"fnv1a64:" in r.stdout, r.stdout
    r = essaim("test", "x.test.toml", "--update", cwd=tmp_path)
    assert r.returncode == 0 and "written, 1 change(s)" in r.stdout and "recording:" in r.stdout
    assert essaim("test", "x.test.toml", cwd=tmp_path).returncode == 0


def test_a_run_past_the_specs_timeout_is_stopped_and_failed(tmp_path):
    spec = spec_text(["each errors == 0"]).replace("seeds = 10\nticks = 5\n", "seeds = [1, 2]\nticks = 100000000\n")
    project(tmp_path, spec + "timeout = 1\n")
    r = essaim("test", "x.test.toml", "-j", "2", cwd=tmp_path, timeout=60)
    assert r.returncode == 1, r.stdout + r.stderr
    assert rows(r.stdout)["every run finishes (exit 0)"] == ("0/2 runs", "FAIL", "1, 2")
    assert "seed 1: stopped after the spec's timeout of 1 s" in r.stdout


def test_a_missing_workdir_is_a_spec_error(tmp_path):
    project(tmp_path, spec_text(["each errors == 0"], extra='workdir = "nowhere"'))
    r = essaim("test", "x.test.toml", cwd=tmp_path)
    assert r.returncode == 2 and "x.test.toml:4: workdir nowhere does not exist" in r.stderr
