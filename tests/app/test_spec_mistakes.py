"""The mistakes of an `essaim test` spec, as a new user makes them (docs/testing.md): each
named with its line and a hint, all at once, in --junit too; a failed seed's rerun command."""
import os
import subprocess
import xml.etree.ElementTree as ET

from clitest import ESSAIM, check_junit_shape, essaim, need_essaim, write
from test_essaim_test import project, rows, spec_text

pytestmark = need_essaim


def junit_failures(path):
    root = ET.parse(path).getroot()
    check_junit_shape(root)
    return [(c.get("name"), f.get("type"), f.text or "") for c in root.iter("testcase") for f in c]


def test_a_metric_no_run_produced_is_a_spec_error_with_the_closest_name(tmp_path):
    expect = ["each errors == 0", "each sed > 0", "mean summary.tiks > 4", "each sed/seed > 0", "mean seed > 0"]
    project(tmp_path, spec_text(expect))
    r = essaim("test", "x.test.toml", "-j", "2", "--junit", "out.xml", cwd=tmp_path)
    assert r.returncode == 2, r.stdout + r.stderr
    table = rows(r.stdout.replace("  ERROR ", "  FAIL "))
    assert table["each sed > 0"][:2] == ("no run has it", "FAIL") and table["mean seed > 0"][1] == "pass"
    said = "x.test.toml:7: expect \"each sed > 0\": no run produced 'sed' (metrics.json); did you mean 'seed'?"
    assert said in r.stdout and said in r.stderr
    assert "x.test.toml:8: expect \"mean summary.tiks > 4\": no run produced 'summary.tiks' (summary.json); " \
           "did you mean 'summary.ticks'?" in r.stderr
    assert "x.test.toml:9:" in r.stderr and "'sed'" in r.stderr  # one side of a ratio
    assert " 0/10 runs" not in r.stdout and "the spec has mistakes" in r.stdout
    failures = junit_failures(tmp_path / "out.xml")
    assert {(name, kind) for name, kind, _ in failures} == {(e, "spec") for e in expect[1:4]}


def test_an_object_or_a_time_series_column_named_as_a_metric_gets_its_own_hint(tmp_path):
    project(tmp_path, "")
    loop = ('function post_step() experiment.timeseries({{"alive", 3}}) end\n'
            "function post_experiment() return {per = {A = 1, B = 2}} end\n")
    write(tmp_path, {"loop.lua": loop, "x.test.toml": spec_text(["each per > 0", "each per.A == 1", "mean alive > 2"])})
    r = essaim("test", "x.test.toml", cwd=tmp_path)
    assert r.returncode == 2, r.stdout + r.stderr
    assert "x.test.toml:6: expect \"each per > 0\": 'per' is an object in metrics.json, not a number: " \
           "name one of its keys (per.A, per.B)" in r.stderr
    assert "x.test.toml:8: expect \"mean alive > 2\": no run produced 'alive' (metrics.json); 'alive' is a " \
           "column of timeseries.csv, which an expectation does not read" in r.stderr
    assert "x.test.toml:7" not in r.stderr and rows(r.stdout.replace("  ERROR ", "  FAIL "))["each per.A == 1"][1] == "pass"


def test_every_mistake_of_a_spec_at_once_with_its_line_and_junit(tmp_path):
    project(tmp_path, "")
    write(tmp_path, {"x.test.toml": 'experiment = "xx.argos"\nseed = 3\nexpect = [\n'
                                    '  "mean seed / ticks > 0",\n  "fraction(seed / ticks < 1) >= 0.5",\n'
                                    '  "meen seed > 1",\n]\n'})
    r = essaim("test", "x.test.toml", "--junit", "out.xml", cwd=tmp_path)
    assert r.returncode == 2 and r.stdout == ""
    lines = r.stderr.splitlines()
    assert lines[0] == "x.test.toml:1: experiment xx.argos does not exist; did you mean 'x.argos'?"
    assert lines[1] == "x.test.toml:2: unknown key 'seed'; did you mean 'seeds'?"
    assert lines[2].startswith("x.test.toml:4: ") and \
        lines[2].endswith("a ratio is written without spaces around '/': 'seed/ticks > 0'")
    assert lines[3].startswith("x.test.toml:5: ") and lines[3].endswith("'seed/ticks < 1'")
    assert lines[4].startswith("x.test.toml:6: ") and "did you mean 'mean'?" in lines[4]
    assert lines[5] == "essaim test: 5 error(s) in x.test.toml; nothing was run"
    [(name, kind, body)] = junit_failures(tmp_path / "out.xml")
    assert kind == "spec" and body.splitlines() == lines[:5]


def test_a_toml_syntax_error_is_said_in_words_with_line_and_column(tmp_path):
    project(tmp_path, 'experiment = "x.argos\nexpect = ["each errors == 0"]\n')
    r = essaim("test", "x.test.toml", "--junit", "out.xml", cwd=tmp_path)
    assert r.returncode == 2
    assert r.stderr.startswith('x.test.toml:1:22: TOML syntax: a string has no closing quote (a "..." ends on the '
                               'line it starts): experiment = "x.argos\n'), r.stderr
    assert "control characters" not in r.stderr
    assert junit_failures(tmp_path / "out.xml")[0][1] == "spec"
    project(tmp_path, 'experiment = "x.argos"\nexpect = ["each errors == 0" "mean seed > 1"]\n')
    r = essaim("test", "x.test.toml", cwd=tmp_path)
    assert r.stderr.startswith("x.test.toml:2:30: TOML syntax: a comma is missing between two items of the list")


def rerun_command(stdout, seed):
    [command] = [ln.split("alone: ", 1)[1] for ln in stdout.splitlines() if f"rerun seed {seed} alone: " in ln]
    return command


def reruns_the_same(command, folder, cwd, tmp_path):
    """The command, run by a shell with essaim on PATH, writes the seed's metrics again."""
    first = (folder / "metrics.json").read_text()
    (folder / "metrics.json").unlink()
    (tmp_path / "bin").mkdir(exist_ok=True)
    if not (tmp_path / "bin" / "essaim").exists():
        (tmp_path / "bin" / "essaim").symlink_to(ESSAIM)
    env = dict(os.environ, PATH=f"{tmp_path / 'bin'}:{os.environ['PATH']}")
    r = subprocess.run(["bash", "-c", command], cwd=cwd, env=env, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return (folder / "metrics.json").read_text() == first


def test_a_failed_seed_prints_the_command_that_reruns_it_alone(tmp_path):
    (tmp_path / "tests").mkdir()
    spec = spec_text(["each seed < 3"], extra='workdir = ".."').replace('"x.argos"', '"../x.argos"')
    project(tmp_path, "")
    write(tmp_path, {"tests/x.test.toml": spec + '[set]\n"framework.experiment.length" = 3\n'})
    r = essaim("test", "tests/x.test.toml", "-j", "2", cwd=tmp_path)
    assert r.returncode == 1
    command = rerun_command(r.stdout, 3)
    assert command == "essaim run x.argos --seed 3 --ticks 5 --out essaim-test/x.test/seed-3 " \
                      "--set framework.experiment.length=3", command
    assert r.stdout.count("rerun seed") == 1
    assert reruns_the_same(command, tmp_path / "essaim-test/x.test/seed-3", tmp_path, tmp_path)
    # From another folder than the spec's workdir: the command goes there in a subshell.
    r = essaim("test", "x.test.toml", cwd=tmp_path / "tests")
    command = rerun_command(r.stdout, 3)
    assert command.startswith(f"(cd {tmp_path.resolve()} && essaim run x.argos --seed 3 ") and command.endswith(")")
    assert reruns_the_same(command, tmp_path / "tests/essaim-test/x.test/seed-3", tmp_path / "tests", tmp_path)


def test_a_correct_spec_still_passes_with_no_hint(tmp_path):
    project(tmp_path, spec_text(["each errors == 0", "mean seed/seed == 1", "fraction(seed > 2) >= 0.8"]))
    r = essaim("test", "x.test.toml", "-j", "2", "--junit", "out.xml", cwd=tmp_path)
    assert r.returncode == 0 and r.stderr == "" and "rerun" not in r.stdout, r.stdout + r.stderr
    assert junit_failures(tmp_path / "out.xml") == []


def test_when_no_run_finished_a_missing_value_is_not_called_a_typo(tmp_path):
    broken = "error('does not load')\n"  # every run fails before any metric: nothing to judge names by
    project(tmp_path, spec_text(["mean sed > 0"]).replace("seeds = 10", "seeds = 2"), broken)
    r = essaim("test", "x.test.toml", cwd=tmp_path)
    assert r.returncode == 1, r.stdout + r.stderr
    table = rows(r.stdout)
    assert table["every run finishes (exit 0)"][1] == table["mean sed > 0"][1] == "FAIL"
    assert "ERROR" not in r.stdout and "did you mean" not in r.stdout + r.stderr
    assert "rerun seed 1 alone: essaim run x.argos --seed 1 --ticks 5 --out essaim-test/x.test/seed-1" in r.stdout
