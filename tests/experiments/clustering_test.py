"""The object-clustering experiment (arenas/clustering.argos) run by essaim.

Foot-bots grip red LED cylinders that the loop functions scattered with add_entity and carry
them into the black zone; the loop functions turn those that arrived blue (set_led_color) and
count them into metrics.json. The count depends much on the seed: after 1000 ticks, over seeds
1-24, it ranged 5-12 (mean 9.1) on main b6d1799, 1-12 (mean 8.7) with the sensors made ARGoS's
(issue 38) and 5-12 (mean 9.1) with the motion made ARGoS's too (issue 41); at the file's seed
it went 12, 9, 5 (cylinders left in the zone can be pushed out again). After 2000 ticks it
ranges 7-12 (mean 11.0) and the file's seed has 11 (with ARGoS's spring hold, issue 52, and the
controller made for it: 5-12, mean 10.3, the file's seed 12): the test asks for 10 in 2000 ticks, so
that a harmless change in the dynamics does not fail it, and checks the mechanisms:
recolouring shows in the recording, the robots' own counters read through r:lua_global reach
the metrics, and threads change nothing.

The runs need the binary: set ESSAIM to its path (ctest does); without it they are skipped.
"""

import json
import os
import struct
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
ARENA = ROOT / "arenas" / "clustering.argos"
TICKS = 2000
BLUE565, RED565 = 0x001F, 0xF800


@pytest.fixture(scope="module")
def essaim():
    path = os.environ.get("ESSAIM")
    if not path or not Path(path).exists():
        pytest.skip("ESSAIM is not set to the essaim binary")
    return path


def run(essaim, out, *extra):
    cmd = [essaim, "run", str(ARENA), "--ticks", str(TICKS), "--out", str(out), "--quiet", *extra]
    proc = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, f"{' '.join(cmd)}\n{proc.stdout}\n{proc.stderr}"
    summary = json.loads((out / "summary.json").read_text())
    assert summary["controller_errors"] == [], summary["controller_errors"]
    return summary, json.loads((out / "metrics.json").read_text())


@pytest.fixture(scope="module")
def recorded(essaim, tmp_path_factory):
    out = tmp_path_factory.mktemp("clustering") / "run"
    summary, metrics = run(essaim, out, "--record")
    return out, summary, metrics


def movable_leds(path):
    """(LED colours RGB565 of the movable obstacles in the last frame, obstacle count, movables)."""
    b = path.read_bytes()
    assert b[:8] == b"ESSAIMRC" and struct.unpack_from("<I", b, 8)[0] == 2
    header, frame = struct.unpack_from("<II", b, 12)
    robots, obstacles, movables, _ = struct.unpack_from("<4I", b, 32)
    last = header + ((len(b) - header) // frame - 1) * frame
    base = last + 4 + 10 * robots
    return [struct.unpack_from("<H", b, base + 8 * j + 6)[0] for j in range(movables)], obstacles, movables


def test_robots_cluster_the_cylinders_in_the_zone(recorded):
    _, summary, m = recorded
    assert m["cylinders"] == 12
    assert m["in_zone"] >= 10, m
    ticks = m["delivery_ticks"]
    assert len(ticks) >= m["in_zone"] and ticks == sorted(ticks) and m["first_delivery_tick"] == ticks[0]
    if m["in_zone"] == 12:
        assert summary["finished_by"] == "loop_functions" and m["all_delivered_tick"] == summary["ticks"]
    assert m["robot_deliveries"] >= 1  # the controllers' global, summed through r:lua_global


def test_recolouring_shows_in_the_recording(recorded):
    out, _, m = recorded
    leds, obstacles, movables = movable_leds(out / "recording.bin")
    assert (obstacles, movables) == (4 + 12, 12)  # the walls, and the cylinders added in init()
    assert leds.count(BLUE565) == m["in_zone"]
    assert leds.count(RED565) == 12 - m["in_zone"]


def test_timeseries_counts_grow(recorded):
    out, _, m = recorded
    rows = (out / "timeseries.csv").read_text().splitlines()
    assert rows[0] == "tick,in_zone,robot_deliveries"
    counts = [int(r.split(",")[1]) for r in rows[1:]]
    assert counts and counts[-1] <= m["in_zone"] and max(counts) >= 5


def test_same_metrics_on_four_threads(essaim, recorded, tmp_path):
    _, _, m = recorded
    _, m4 = run(essaim, tmp_path / "t4", "--threads", "4")
    assert m4 == m
