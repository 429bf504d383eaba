"""The command line's error paths: bad arguments and bad files exit 2 with a message naming
the problem; a controller error is exit 0 (counted) or 1 with --strict."""
import json
import os
import subprocess
from pathlib import Path

import pytest

ESSAIM = os.environ.get("ESSAIM")
DATA = Path(__file__).resolve().parents[1] / "data"
pytestmark = pytest.mark.skipif(not ESSAIM, reason="ESSAIM (the essaim binary) is not set")


def run(*args, cwd=None):
    return subprocess.run([ESSAIM, *map(str, args)], capture_output=True, text=True, timeout=60, cwd=cwd)


@pytest.mark.parametrize("args, message", [
    (["run"], "FILE.argos is required"),
    (["run", DATA / "tiny.argos", "--ticks", "ten"], "--ticks: 'ten' is not a whole number"),
    (["run", DATA / "tiny.argos", "--warp"], "unknown option --warp"),
    (["run", DATA / "tiny.argos", "--seed"], "--seed needs a value"),
    (["run", "no/such/file.argos"], "no/such/file.argos: cannot read the experiment file"),
    (["check", DATA / "tiny.argos", "--set", "nope"], "expected PATH=VALUE"),
    (["fly"], "unknown command 'fly'"),
])
def test_bad_input_exits_2_with_a_message(args, message):
    r = run(*args)
    assert r.returncode == 2, r.stderr
    assert message in r.stderr


def test_controller_error_is_counted_or_fatal_with_strict(tmp_path):
    (tmp_path / "bad.lua").write_text("function step() error('boom') end\n")
    argos = (DATA / "tiny.argos").read_text()
    (tmp_path / "x.argos").write_text(argos)
    script = f"controllers.{_controller_id(argos)}.params.script=bad.lua"
    r = run("run", tmp_path / "x.argos", "--ticks", 3, "--quiet", "--out", tmp_path / "a", "--set", script)
    assert r.returncode == 0, r.stderr
    summary = json.loads((tmp_path / "a" / "summary.json").read_text())
    assert summary["status"] == "controller_error"
    assert "boom" in summary["controller_errors"][0]["message"]
    r = run("run", tmp_path / "x.argos", "--ticks", 3, "--quiet", "--strict", "--out", tmp_path / "b",
            "--set", script)
    assert r.returncode == 1
    assert "bad.lua:1: boom" in r.stderr


def _controller_id(argos_text):
    start = argos_text.index('<lua_controller id="') + len('<lua_controller id="')
    return argos_text[start:argos_text.index('"', start)]
