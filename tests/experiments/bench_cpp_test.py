"""`essaim bench`'s C++ scenarios (avoidance-cpp-*): bench/avoidance_cpp, the C++ twin of
avoidance.lua built with essaim into build/bench, found through ARGOS_PLUGIN_PATH (which bench
extends, keeping what the user set), takes the same decisions as the Lua controller: the same
recording; and it runs in the bench table beside the Lua scenario (no timing threshold)."""
import os
import subprocess
import sys
from pathlib import Path

import pytest

ESSAIM = os.path.abspath(os.environ.get("ESSAIM", "build/essaim"))
ROOT = Path(__file__).resolve().parents[2]
PLUGINS = Path(ESSAIM).resolve().parent / "bench"


def bench(*args, env=None):
    return subprocess.run([ESSAIM, "bench", *args], capture_output=True, text=True, timeout=300,
                          env=dict(os.environ, **(env or {})))


def test_cpp_scenario_runs_beside_the_lua_one():
    # A plugin path of the user's own stays first; bench's folder is added after it.
    r = bench("--only", "avoidance-100,avoidance-cpp-100", "--ticks", "5", env={"ARGOS_PLUGIN_PATH": "/nonexistent"})
    assert r.returncode == 0, r.stderr
    lines = r.stdout.strip().splitlines()
    header = lines[0].split()
    rows = {line.split()[0]: dict(zip(header, line.split())) for line in lines[1:]}
    assert set(rows) == {"avoidance-100", "avoidance-cpp-100"}
    for row in rows.values():
        assert row["robots"] == "100" and float(row["us/r-step"]) > 0
    assert float(rows["avoidance-cpp-100"]["luaKB/r"]) == 0 and float(rows["avoidance-100"]["luaKB/r"]) > 0


def test_floor_skips_a_cpp_scenario_and_says_why():
    r = bench("--floor", "--only", "avoidance-cpp-100", "--ticks", "2")
    assert r.returncode == 0, r.stderr
    assert "avoidance-cpp-100: --floor times Lua controllers" in r.stderr and len(r.stdout.splitlines()) == 1


def test_the_cpp_twin_takes_avoidance_luas_decisions():
    """150 robots, 60 ticks through the Python module: every pose equal to the last bit."""
    module = Path(ESSAIM).resolve().parent / "python"
    if not any(module.glob("essaim*.so")) or os.environ.get("ESSAIM_SANITIZED") == "1":
        pytest.skip("the Python module is not built (or runs under ASan)")
    script = """
import essaim, numpy as np
poses = []
for name in ("avoidance_1000", "avoidance_cpp_1000"):
    with essaim.Simulation(name + ".argos", seed=5, overrides={"arena.distribute[2].entity.quantity": 150}) as s:
        s.step(60)
        poses.append(s.poses())
        assert s.errors == []
print(np.array_equal(poses[0], poses[1]), np.abs(poses[1] - poses[0]).max())
"""
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300, cwd=ROOT / "bench",
                       env=dict(os.environ, ARGOS_PLUGIN_PATH=str(PLUGINS), PYTHONPATH=str(module)))
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith("True"), r.stdout


def test_an_installed_essaim_finds_its_bench_controller(tmp_path):
    """cmake --install puts the library in lib/essaim/bench, where the installed bench looks."""
    prefix = tmp_path / "prefix"
    build = Path(ESSAIM).resolve().parent
    done = subprocess.run(["cmake", "--install", str(build), "--prefix", str(prefix)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert (prefix / "lib" / "essaim" / "bench" / "libbench_avoidance.so").is_file()
    env = {k: v for k, v in os.environ.items() if k != "ARGOS_PLUGIN_PATH"}
    r = subprocess.run([str(prefix / "bin" / "essaim"), "bench", "--only", "avoidance-cpp-100", "--ticks", "2"],
                       capture_output=True, text=True, timeout=120, cwd=tmp_path, env=env)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines()[1].split()[:2] == ["avoidance-cpp-100", "100"]
