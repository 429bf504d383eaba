"""bench/scale_cores.py runs the scaled swarm over regions × threads, reads each run's
summary.json and projects to more cores (no timing threshold)."""
import json
import os
import subprocess
import sys

ESSAIM = os.environ.get("ESSAIM", "build/essaim")
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "bench"))
import scale_cores  # noqa: E402


def test_overrides_grow_the_arena_at_constant_density():
    o = scale_cores.scale_overrides(4000)  # twice the side of the 1 000-robot arena
    assert o["arena.size"] == "64,64,1"
    assert o["arena.wall_east.body.position"] == "32,0,0"
    assert o["arena.distribute[2].entity.quantity"] == 4000
    assert o["arena.distribute[0].entity.quantity"] == 400  # 100 boxes per 1 000 robots
    assert o["arena.distribute[0].position.max"] == "30,30,0"


def test_runs_every_pair_and_projects(tmp_path):
    out = tmp_path / "rows.json"
    r = subprocess.run([sys.executable, os.path.join(ROOT, "bench", "scale_cores.py"), "--essaim", ESSAIM,
                        "--sizes", "300", "--threads", "1,2", "--regions", "1,same", "--ticks", "3",
                        "--json", str(out), "--project", "4,64"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    rows = json.loads(out.read_text())
    # (threads, regions): both counts at 1 and 2 threads, and 2 regions on 1 thread for the fit.
    assert sorted((x["threads"], x["regions"]) for x in rows) == [(1, 1), (1, 2), (2, 1), (2, 2)]
    for x in rows:
        assert x["robots"] == 300 and x["wall_ms"] > 0 and x["phys_ms"] > 0
        assert abs(x["rtf"] - 100 / x["wall_ms"]) < 1e-6 * x["rtf"]  # 0.1 s ticks
        # One thread: the stages fit inside the tick's wall time.
        if x["threads"] == 1:
            assert x["phys_ms"] + x["sense_cpu_ms"] + x["ctrl_cpu_ms"] <= x["wall_ms"] * 1.001
    projected = [line.split() for line in r.stdout.splitlines()[-2:]]
    assert [p[:3] for p in projected] == [["300", "4", "4"], ["300", "64", "64"]]
    assert 0 < float(projected[0][3]) <= float(projected[1][3])  # more cores, never slower
