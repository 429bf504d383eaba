"""`essaim bench scale` runs the avoidance scenario at growing sizes and prints sane numbers
(no timing threshold)."""
import os
import subprocess

ESSAIM = os.environ.get("ESSAIM", "build/essaim")


def run_scale(*args):
    return subprocess.run([ESSAIM, "bench", "scale", *args], capture_output=True, text=True, timeout=300)


def test_scale_prints_one_row_per_size_with_consistent_numbers():
    r = run_scale("--sizes", "100,400", "--ticks", "5", "--threads", "2")
    assert r.returncode == 0, r.stderr
    lines = r.stdout.strip().splitlines()
    header = lines[0].split()
    assert header == [
        "robots", "setup-s", "setup-cpu", "down-s", "us/r-step", "vs-first", "phys", "sense", "ctrl", "other", "peakKB/r",
        "rtf-1", "rtf-2", "setup-2"
    ]
    assert len(lines) == 3
    rows = [dict(zip(header, line.split())) for line in lines[1:]]
    # Each size's cost over the first size's (printed to 0.01 each).
    assert rows[0]["vs-first"] == "1.00"
    ratio = float(rows[1]["us/r-step"]) / float(rows[0]["us/r-step"])
    assert abs(float(rows[1]["vs-first"]) - ratio) <= 0.01 * ratio + 0.01
    for line, robots in zip(lines[1:], (100, 400)):
        row = dict(zip(header, line.split()))
        assert int(row["robots"]) == robots  # the scenario scaled to the size asked
        cost = float(row["us/r-step"])
        parts = [float(row[k]) for k in ("phys", "sense", "ctrl")]
        # A hundred robots may be made in under 5 ms, printed 0.00.
        assert float(row["setup-s"]) >= 0 and cost > 0 and all(p > 0 for p in parts)
        # The set-up's CPU seconds: one thread's (the watchdog's wake-ups take next to
        # nothing), so at most its wall time, printed to 0.01 s.
        assert 0 <= float(row["setup-cpu"]) <= float(row["setup-s"]) + 0.05
        # Freeing a few hundred robots takes far less than making them (printed to 0.01 s).
        assert 0 <= float(row["down-s"]) <= float(row["setup-s"]) + 0.01
        # The stages and the rest add up to the whole (rounded to 0.01 each).
        assert abs(sum(parts) + float(row["other"]) - cost) <= 0.05
        # A Lua state per robot alone is tens of KB; the process is far from a GB a robot.
        assert 10 < float(row["peakKB/r"]) < 1e6
        # 5 ticks of 0.1 s: the real-time factor is the simulated 0.5 s over the wall time.
        assert float(row["rtf-1"]) > 0 and float(row["rtf-2"]) > 0
        # The set-up again, on 2 threads (the Lua states are made on the pool); a few
        # hundred robots take milliseconds, printed to 0.01 s.
        assert 0 <= float(row["setup-2"]) <= float(row["setup-s"]) + 1


def test_scale_warmup_is_an_option_with_a_default_and_a_range():
    r = run_scale("--help")
    assert r.returncode == 0 and "--warmup N=20" in r.stdout
    r = run_scale("--sizes", "50", "--ticks", "2", "--warmup", "0", "--threads", "1")
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip().splitlines()[1].split()[0] == "50"
    r = run_scale("--sizes", "50", "--ticks", "2", "--warmup", "-1")
    assert r.returncode == 2 and "--warmup" in r.stderr


def test_scale_on_one_thread_prints_no_second_factor():
    r = run_scale("--sizes", "50", "--ticks", "2", "--threads", "1")
    assert r.returncode == 0, r.stderr
    header, row = r.stdout.strip().splitlines()
    assert header.split()[-2:] == ["peakKB/r", "rtf-1"]
    assert len(row.split()) == len(header.split()) and row.split()[0] == "50"


def test_scale_refuses_a_missing_folder_and_an_unknown_option():
    r = run_scale("--sizes", "50", "--ticks", "2", "--dir", "/nonexistent")
    assert r.returncode == 2 and "avoidance_1000.argos" in r.stderr
    r = run_scale("--size", "50")
    assert r.returncode == 2 and "--sizes" in r.stderr
