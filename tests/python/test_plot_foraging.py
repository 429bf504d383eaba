"""plot_foraging.py on synthetic sweep folders shaped like the shipped foraging sweeps."""
import json
import subprocess
import sys

from conftest import SCRIPTS, need_python_deps

need_python_deps()
import pandas as pd  # noqa: E402

EPS = "controllers.foraging.params.EPSILONGREED"


def sweep_folder(path, rows, drain="0.1"):
    path.mkdir()
    pd.DataFrame(rows).to_parquet(path / "results.parquet", index=False)
    (path / "sweep.json").write_text(json.dumps(
        {"set": {"controllers.foraging.params.BATT_BY_STEP": drain}}))
    return path


def run_row(robots, seed, a, b, c, **more):
    row = {"run": f"r{robots}_{seed}", "status": "ok", "seed": seed, "robots": robots,
           "trips_total": a + b + c, "trips_per_source.A": a, "trips_per_source.B": b,
           "trips_per_source.C": c, "trips_per_robot_mean": (a + b + c) / robots}
    row.update(more)
    return row


def plot(*args):
    return subprocess.run([sys.executable, str(SCRIPTS / "plot_foraging.py"), *map(str, args)],
                          capture_output=True, text=True, timeout=120)


def test_shares_medians_and_figures(tmp_path):
    rows = [run_row(10, s, 80 + s, 10, 10 - s) for s in (1, 2, 3)]
    rows += [run_row(30, s, 60, 20 + s, 20) for s in (1, 2, 3)]
    rows.append({"run": "failed", "status": "failed", "seed": 4, "robots": 10})
    folder = sweep_folder(tmp_path / "d01", rows)
    r = plot("shares", folder, "--out", tmp_path / "fig")
    assert r.returncode == 0, r.stderr
    # A at 10 robots: 81/100, 82/100, 83/100 -> median 82 %; the failed run is left out
    assert "drain 0.1: 10 robots: A 82.0 % of trips (median)" in r.stdout
    assert "drain 0.1: 30 robots: B 21.6 % of trips (median)" in r.stdout   # 22/102
    for fmt in ("png", "svg"):
        assert (tmp_path / "fig" / f"source_shares.{fmt}").stat().st_size > 1000


def test_epsilon_best_and_figures(tmp_path):
    rows = []
    for eps, trips in ((0.0, 100), (0.1, 140), (0.2, 120)):
        for s in (1, 2, 3):
            rows.append(run_row(10, s, trips - 20, 10, 10 + s, **{EPS: eps}))
    folder = sweep_folder(tmp_path / "eps", rows, drain="0.2")
    r = plot("epsilon", folder, "--out", tmp_path / "fig")
    assert r.returncode == 0, r.stderr
    assert "10 robots: most trips at eps 0.1" in r.stdout
    assert "eps 0: 10.20" in r.stdout    # 101, 102, 103 trips by 10 robots: median 10.2
    assert (tmp_path / "fig" / "epsilon.png").stat().st_size > 1000


def test_epsilon_wants_one_sweep(tmp_path):
    r = plot("epsilon", tmp_path / "a", tmp_path / "b")
    assert r.returncode == 2 and "one sweep folder" in r.stderr
