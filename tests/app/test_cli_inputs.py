"""Inputs that used to be accepted in silence: --set paths nobody reads, unknown
attributes in the file (warnings; errors under --strict), a controller without a script,
robots placed on each other."""
import json
import os
import subprocess
from pathlib import Path

import pytest

ESSAIM = os.environ.get("ESSAIM")
DATA = Path(__file__).resolve().parents[1] / "data"
pytestmark = pytest.mark.skipif(not ESSAIM, reason="ESSAIM (the essaim binary) is not set")


def run(*args, cwd=DATA):
    return subprocess.run([ESSAIM, *map(str, args)], capture_output=True, text=True, timeout=60, cwd=cwd)


@pytest.mark.parametrize("command", ["check", "run"])
@pytest.mark.parametrize("path, hint", [
    ("arena.distribute.entity.quantiy", "did you mean 'quantity'?"),
    ("framework.experiment.lenght", "did you mean 'length'?"),
    ("controllers.ctrl.sensors.positioning.pos_noise_rnage", "did you mean 'pos_noise_range'?"),
])
def test_set_of_an_attribute_nobody_reads_exits_2(tmp_path, command, path, hint):
    r = run(command, "tiny.argos", "--quiet", "--set", f"{path}=5", "--out", tmp_path / "o") \
        if command == "run" else run(command, "tiny.argos", "--set", f"{path}=5")
    assert r.returncode == 2, r.stderr
    assert f"tiny.argos:" in r.stderr and f"--set {path}=5" in r.stderr
    assert hint in r.stderr
    if command == "run":  # nothing ran; the summary says why (docs/cli.md)
        s = json.loads((tmp_path / "o" / "summary.json").read_text())
        assert s["status"] == "failed" and s["ticks"] == 0 and hint in s["failure"]


def test_set_file_entries_are_checked_too(tmp_path):
    (tmp_path / "o.json").write_text('{"arena.distribute.entity.quantiy": 50}')
    r = run("check", "tiny.argos", "--set-file", tmp_path / "o.json")
    assert r.returncode == 2
    assert "did you mean 'quantity'?" in r.stderr


def _with_typo(tmp_path):
    text = (DATA / "tiny.argos").read_text().replace('<foot-bot id="fb">', '<foot-bot id="fb" rab_rnage="2">')
    (tmp_path / "typo.argos").write_text(text)
    return tmp_path / "typo.argos"


@pytest.mark.parametrize("command", ["check", "run"])
def test_unknown_attribute_in_the_file_warns_and_strict_refuses(tmp_path, command):
    f = _with_typo(tmp_path)
    extra = ["--ticks", 2, "--out", tmp_path / "o"] if command == "run" else []
    r = run(command, f, *extra)
    assert r.returncode == 0, r.stderr
    assert "typo.argos:29: <foot-bot>: warning: unknown attribute 'rab_rnage' (essaim does not read it); " \
           "did you mean 'rab_range'?" in r.stderr
    r = run(command, f, "--strict", *extra)
    assert r.returncode == 2
    assert "typo.argos:29: <foot-bot>: unknown attribute 'rab_rnage'" in r.stderr


def test_bench_strict_refuses_a_scenario_with_an_unknown_attribute(tmp_path):
    (tmp_path / "avoidance_1000.argos").write_text(
        (DATA / "tiny.argos").read_text().replace('<foot-bot id="fb">', '<foot-bot id="fb" rab_rnage="2">'))
    (tmp_path / "tiny.lua").write_text((DATA / "tiny.lua").read_text())
    r = run("bench", "--dir", tmp_path, "--only", "avoidance-1000", "--ticks", 1, "--threads", 1, "--strict",
            cwd=tmp_path)
    assert r.returncode == 2, r.stdout + r.stderr
    assert "unknown attribute 'rab_rnage'" in r.stderr


def test_controller_without_script_names_it(tmp_path):
    text = (DATA / "tiny.argos").read_text().replace('script="tiny.lua" ', "")
    (tmp_path / "x.argos").write_text(text)
    r = run("check", tmp_path / "x.argos")
    assert r.returncode == 2
    assert "x.argos:12: <lua_controller>: lua_controller 'ctrl' has no script" in r.stderr


def test_overlapping_robots_are_refused_with_file_and_line(tmp_path):
    bots = ''.join(f'<foot-bot id="b{i}"><body position="0.{i},0,0" orientation="0,0,0"/>'
                   f'<controller config="ctrl"/></foot-bot>\n' for i in range(2))
    text = (DATA / "tiny.argos").read_text().replace("<distribute>", bots + "<distribute>")
    (tmp_path / "x.argos").write_text(text)
    r = run("check", tmp_path / "x.argos", cwd=DATA)
    assert r.returncode == 2
    assert "x.argos:26: <foot-bot>: foot-bot 'b1' overlaps foot-bot 'b0' (line 25)" in r.stderr
