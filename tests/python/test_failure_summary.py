"""Every failure of `essaim run` leaves summary.json (status "failed", the message) in the
output folder and exits with the code docs/cli.md gives: 2 for bad input, including a
controller that does not load, a missing script or a bad floor image; 1 when the run cannot
write an output (the recording, memory.csv)."""
import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

ESSAIM = os.environ.get("ESSAIM")
DATA = Path(__file__).parent / "data"
pytestmark = pytest.mark.skipif(not ESSAIM, reason="ESSAIM (the essaim binary) is not set")


@pytest.fixture
def folder(tmp_path):
    for f in ("tiny.argos", "tiny.lua"):
        shutil.copy(DATA / f, tmp_path)
    return tmp_path


def variant(folder, name, old, new):
    text = (folder / "tiny.argos").read_text()
    assert old in text
    (folder / name).write_text(text.replace(old, new, 1))
    return name


def run(folder, *args):
    r = subprocess.run([ESSAIM, "run", *map(str, args), "-q", "--out", "out"], cwd=folder,
                       capture_output=True, text=True, timeout=60)
    summary = folder / "out" / "summary.json"
    return r, json.loads(summary.read_text()) if summary.exists() else None


def assert_failed(summary, message):
    assert summary is not None, "no summary.json"
    assert summary["status"] == "failed" and summary["finished_by"] == "error"
    assert message in summary["failure"], summary["failure"]
    assert summary["outputs"] == ["summary.json"]


def test_missing_controller_script(folder):
    f = variant(folder, "x.argos", 'script="tiny.lua"', 'script="missing.lua"')
    r, s = run(folder, f)
    assert r.returncode == 2, r.stderr
    assert_failed(s, "x.argos:20: <params>: script 'missing.lua' not found")
    assert s["ticks"] == 0 and s["experiment"] == "x.argos"


def test_bad_floor_image(folder):
    (folder / "bad.png").write_bytes(b"\x89PNG\r\n\x1a\nnot really")
    f = variant(folder, "x.argos", '<arena size="4, 4, 1" center="0, 0, 0.5">',
                '<arena size="4, 4, 1" center="0, 0, 0.5"><floor id="f" source="image" path="bad.png"/>')
    r, s = run(folder, f)
    assert r.returncode == 2, r.stderr
    assert_failed(s, "<floor>: floor image 'bad.png'")


def test_controller_that_does_not_load(folder):
    (folder / "bad.lua").write_text("function step( end\n")
    f = variant(folder, "x.argos", 'script="tiny.lua"', 'script="bad.lua"')
    r, s = run(folder, f)
    assert r.returncode == 2, r.stderr
    assert_failed(s, "robot fb0: bad.lua:1:")
    assert s["robots"] == 4 and s["seed"] == 1 and s["experiment_hash"].startswith("fnv1a64:")


def test_bad_set_path(folder):
    r, s = run(folder, "tiny.argos", "--set", "arena.nothing.here=1")
    assert r.returncode == 2, r.stderr
    assert_failed(s, "nothing")
    assert s["overrides"] == ["arena.nothing.here=1"]


def test_recording_that_cannot_be_written(folder):
    (folder / "out" / "recording.bin").mkdir(parents=True)   # the final rename fails
    r, s = run(folder, "tiny.argos", "--record")
    assert r.returncode == 1, r.stderr
    assert s["status"] == "failed" and "recording.bin" in s["failure"]
    assert "recording.bin" not in s["outputs"] and s["ticks"] == 50
    assert not [p for p in (folder / "out").iterdir() if ".tmp." in p.name]


def test_memory_log_that_cannot_be_opened(folder):
    (folder / "out" / "memory.csv").mkdir(parents=True)
    r, s = run(folder, "tiny.argos", "--record", "--memory-log", "5")
    assert r.returncode == 1, r.stderr
    assert_failed(s, "cannot write out/memory.csv")
    assert s["ticks"] == 0
    assert not [p for p in (folder / "out").iterdir() if ".tmp." in p.name]
