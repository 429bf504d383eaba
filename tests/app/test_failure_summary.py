"""Every failure of `essaim run` leaves summary.json (status "failed", the message) in the
output folder and exits with the code docs/cli.md gives: 2 for bad input, including a
controller that does not load, a missing script or a bad floor image; 1 when the run cannot
write an output (the recording, memory.csv)."""
import json
import os
import resource
import signal
import shutil
import subprocess
from pathlib import Path

import pytest

ESSAIM = os.environ.get("ESSAIM")
DATA = Path(__file__).resolve().parents[1] / "data"
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


@pytest.mark.parametrize("name", ["recording.bin", "memory.csv"])
def test_an_output_name_taken_by_a_folder_is_refused_before_the_run(folder, name):
    (folder / "out" / name).mkdir(parents=True)   # it could never be written
    r, s = run(folder, "tiny.argos", "--record", "--memory-log", "5")
    assert r.returncode == 2, r.stderr
    assert name in r.stderr and "--out" in r.stderr
    assert s is None and (folder / "out" / name).is_dir()


def test_memory_log_that_cannot_be_written_fails_the_run_with_a_summary(folder):
    def file_size_limit():  # writes past 4 KiB fail with EFBIG, as on a full disk
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))
    r = subprocess.run([ESSAIM, "run", "tiny.argos", "--ticks", "500", "--memory-log", "1", "-q", "--out", "out"],
                       cwd=folder, capture_output=True, text=True, timeout=60, preexec_fn=file_size_limit)
    assert r.returncode == 1, r.stderr
    assert "memory.csv: File too large" in r.stderr
    s = json.loads((folder / "out" / "summary.json").read_text())
    assert s["status"] == "failed" and "memory.csv" in s["failure"]
    assert "memory.csv" not in s["outputs"] and s["ticks"] == 500
