"""`essaim bench --floor` runs and prints sane numbers (no timing threshold)."""
import os
import subprocess

ESSAIM = os.environ.get("ESSAIM", "build/essaim")


def test_floor_prints_wall_floor_ratio_and_stage_shares():
    r = subprocess.run([ESSAIM, "bench", "--floor", "--only", "foraging-30", "--ticks", "5", "--threads", "1,2"],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    lines = r.stdout.strip().splitlines()
    header = lines[0].split()
    assert header[:10] == ["scenario", "robots", "thr", "ticks", "wall-us/rs", "floor-us/rs", "wall/floor", "cpu-us/rs",
                           "floor-cpu", "cpu/floor"]
    assert len(lines) == 3  # one row per thread count
    for line, threads in zip(lines[1:], (1, 2)):
        row = dict(zip(header, line.split()))
        assert row["scenario"] == "foraging-30" and row["robots"] == "30" and row["thr"] == str(threads)
        assert row["ticks"] == "5"
        wall, floor, ratio = float(row["wall-us/rs"]), float(row["floor-us/rs"]), float(row["wall/floor"])
        assert wall > 0 and floor > 0
        assert abs(ratio - wall / floor) <= 0.01 * ratio + 0.01
        cpu, floor_cpu, cpu_ratio = float(row["cpu-us/rs"]), float(row["floor-cpu"]), float(row["cpu/floor"])
        assert cpu > 0 and 0 < floor_cpu <= floor * 1.1 + 1  # CPU time does not exceed wall time (one thread)
        assert abs(cpu_ratio - cpu / floor_cpu) <= 0.01 * cpu_ratio + 0.01
        shares = [float(row[k]) for k in ("act%", "phys%", "media%", "loop%", "sense%", "lua%")]
        assert all(0 <= s <= 100 * threads for s in shares)  # sense and control are summed over threads
        if threads == 1:  # summed over threads otherwise; the rest is between stages (more on a busy machine)
            assert 50 <= sum(shares) <= 100.5
            assert float(row["lua%"]) > 0 and float(row["sense%"]) > 0  # foraging senses and thinks


def test_floor_reports_a_broken_scenario_folder():
    r = subprocess.run([ESSAIM, "bench", "--floor", "--only", "foraging-30", "--dir", "/nonexistent"],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and "foraging" in r.stderr
