"""Every shipped experiment gives the same outputs as the committed hashes: a refactor that
claims "behaviour unchanged" is checked bit for bit, not by eye.

Each case runs a fixed seed for a fixed number of ticks with --record and hashes the files the
run writes (recording, metrics, time series). A new arena or scenario without a committed
hash fails here. After a change that is meant to move results, regenerate with
    ESSAIM=build/essaim python tests/sim/golden_test.py --update
and say why in the commit."""
import hashlib
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
HASHES = Path(__file__).with_name("golden_hashes.json")
ESSAIM = os.environ.get("ESSAIM")
OUTPUTS = ("recording.bin", "metrics.json", "timeseries.csv")

# Large scenarios are cut to 100 robots so the whole check stays fast; the code paths are the same.
SMALL_BENCH = ["--set", "arena.distribute[2].entity.quantity=100"]
OVERRIDES = {
    "arenas/foraging_30m.argos": ["--set", "arena.distribute.entity.quantity=100"],
    "bench/avoidance_1000.argos": SMALL_BENCH,
    "bench/camera_1000.argos": SMALL_BENCH,
    "bench/diffusion_1000.argos": SMALL_BENCH,
    "bench/rab_1000.argos": SMALL_BENCH,
    "bench/rays_1000.argos": SMALL_BENCH,
}


def cases():
    files = sorted(ROOT.glob("arenas/*.argos")) + sorted(ROOT.glob("bench/*.argos"))
    files += sorted(ROOT.glob("tests/devices/rays_*.argos"))
    return [str(f.relative_to(ROOT)) for f in files]


def run_case(case, out, threads):
    ticks = "300" if case.startswith("arenas/") else "150"
    cmd = [ESSAIM, "run", case, "--ticks", ticks, "--seed", "11", "--threads", str(threads),
           "--out", str(out), "--record"] + OVERRIDES.get(case, [])
    # bench/avoidance_cpp_1000.argos's controller library is built with essaim, into build/bench.
    env = dict(os.environ, ARGOS_PLUGIN_PATH=str(Path(ESSAIM).resolve().parent / "bench"))
    done = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=300, env=env)
    assert done.returncode == 0, f"{' '.join(cmd)}\n{done.stderr[-2000:]}"
    return {name: hashlib.sha256((out / name).read_bytes()).hexdigest()
            for name in OUTPUTS if (out / name).exists()}


@pytest.mark.skipif(not ESSAIM, reason="ESSAIM (the essaim binary) is not set")
@pytest.mark.parametrize("case", cases())
def test_outputs_match_committed_hashes(case, tmp_path):
    expected = json.loads(HASHES.read_text())
    assert case in expected, f"{case} has no committed hash: run this file with --update"
    assert run_case(case, tmp_path / "one", threads=1) == expected[case]


@pytest.mark.skipif(not ESSAIM, reason="ESSAIM (the essaim binary) is not set")
@pytest.mark.parametrize("case", ["arenas/foraging.argos", "bench/rab_1000.argos"])
def test_two_threads_give_the_same_outputs(case, tmp_path):
    expected = json.loads(HASHES.read_text())
    assert run_case(case, tmp_path / "two", threads=2) == expected[case]


if __name__ == "__main__":
    assert ESSAIM and sys.argv[1:] == ["--update"], __doc__
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        table = {case: run_case(case, Path(tmp) / case.replace("/", "_"), 1) for case in cases()}
    HASHES.write_text(json.dumps(table, indent=2, sort_keys=True) + "\n")
    print(f"wrote {len(table)} cases to {HASHES}")
