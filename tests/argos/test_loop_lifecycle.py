"""C++ loop functions at ARGoS's points of start-up and shut-down (docs/loop-functions.md):
the floor is sampled after Init(), Destroy() runs at the end of the run while the robots'
controllers still exist, LOG outside any hook reaches essaim's log, and a bad element read
by GetNodeAttribute is bad input naming the .argos file and line."""
import json
import subprocess

import pytest

from argos_projects import ESSAIM, HERE, build_project, need_essaim, run

pytestmark = need_essaim


@pytest.fixture(scope="module")
def lifecycle(tmp_path_factory):
    return build_project(HERE / "lifecycle_project", tmp_path_factory.mktemp("lifecycle"))


def test_floor_drawn_from_a_zone_init_reads_shows_at_tick_1(lifecycle, tmp_path):
    done = run(lifecycle / "lifecycle.argos", "--log-prefix", "--out", str(tmp_path / "out"), cwd=lifecycle)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert any(line.endswith("[t=1 inside] ground 0.0") or "inside] ground 0.0" in line for line in lines), lines
    assert any("outside] ground 1.0" in line for line in lines), lines


def test_destroy_reads_the_robots_lua_state_and_its_log_is_kept(lifecycle, tmp_path):
    done = run(lifecycle / "lifecycle.argos", "--out", str(tmp_path / "out"), cwd=lifecycle)
    assert done.returncode == 0, done.stderr
    assert "lifecycle: destroy inside steps 5" in done.stdout
    assert "lifecycle: destroy outside steps 5" in done.stdout
    assert "GetLuaState" not in done.stderr and "error" not in done.stderr.lower()
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["status"] == "ok"


def test_log_outside_any_hook_reaches_essaims_log(lifecycle, tmp_path):
    done = run(lifecycle / "lifecycle.argos", "--log-prefix", "--out", str(tmp_path / "out"), cwd=lifecycle)
    assert done.returncode == 0, done.stderr
    loaded = [line for line in done.stdout.splitlines() if line.endswith("lifecycle: library loaded")]
    assert len(loaded) == 1 and loaded[0] != "lifecycle: library loaded", done.stdout  # prefixed as a log line
    assert "library loaded" not in done.stderr


def test_a_missing_attribute_names_the_argos_file_line_and_element(lifecycle, tmp_path):
    done = run(lifecycle / "bad_zone.argos", "--out", str(tmp_path / "out"), cwd=lifecycle)
    assert done.returncode == 2, (done.returncode, done.stderr)
    assert "bad_zone.argos:14: <zone>: missing attribute 'radius'" in done.stderr, done.stderr
    assert "argos_configuration.h" not in done.stderr


def test_check_says_a_run_with_no_length_ends_only_if_the_cpp_loop_functions_end_it(lifecycle):
    # Whether a C++ class overrides IsExperimentFinished cannot be seen: check warns, saying so.
    done = subprocess.run([ESSAIM, "check", "lifecycle.argos", "--set", "framework.experiment.length=0"],
                          cwd=lifecycle, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert ("lifecycle.argos: warning: the run has no end: no length in <experiment> and no --ticks, so it "
            "runs until Ctrl-C unless the loop functions end it (IsExperimentFinished)") in done.stderr
    assert "no length;" in done.stdout
