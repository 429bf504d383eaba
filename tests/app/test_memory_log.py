"""`essaim run --memory-log N` (memory.csv) and tools/soak.py on a tiny experiment."""
import csv
import os
import subprocess
import sys
from pathlib import Path

import pytest

ESSAIM = os.environ.get("ESSAIM")
DATA = Path(__file__).resolve().parents[1] / "data"
ROOT = Path(__file__).resolve().parents[2]
pytestmark = pytest.mark.skipif(not ESSAIM, reason="ESSAIM (the essaim binary) is not set")


def test_memory_log_samples_every_n_ticks(tmp_path):
    r = subprocess.run([ESSAIM, "run", "tiny.argos", "--ticks", "40", "--memory-log", "10", "-q",
                        "--out", tmp_path], cwd=DATA, capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    rows = list(csv.DictReader(open(tmp_path / "memory.csv")))
    assert [int(x["tick"]) for x in rows] == [10, 20, 30, 40]
    for x in rows:
        assert int(x["rss_bytes"]) > 1 << 20            # a live process holds more than 1 MiB
        assert 0 < int(x["lua_bytes"]) <= int(x["lua_peak_bytes"])
        assert int(x["loop_lua_bytes"]) == 0             # tiny.argos has no loop functions
    summary = (tmp_path / "summary.json").read_text()
    assert '"memory.csv"' in summary


def test_memory_log_refuses_zero(tmp_path):
    r = subprocess.run([ESSAIM, "run", "tiny.argos", "--memory-log", "0", "--out", tmp_path], cwd=DATA,
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and "--memory-log: '0' is out of range" in r.stderr


def test_soak_script_writes_a_table_and_a_figure(tmp_path):
    pytest.importorskip("matplotlib")
    r = subprocess.run([sys.executable, ROOT / "tools/soak.py", "--essaim", ESSAIM, "--ticks", "200",
                        "--experiment", DATA / "tiny_loop.argos", "--out", tmp_path / "run",
                        "--bench-dir", tmp_path / "bench", "--name", "tiny"],
                       cwd=DATA, capture_output=True, text=True, timeout=120)
    assert r.returncode in (0, 1), r.stderr               # 1: not flat (too short to say)
    table = (tmp_path / "bench/tiny.md").read_text()
    assert "| resident set |" in table and "200 samples" in table
    assert (tmp_path / "bench/tiny-memory.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
