"""sweep.py against the essaim binary in $ESSAIM: a tiny sweep run locally and on a Dask
LocalCluster, resuming, failed runs, and metrics from loop functions."""
import json
import shutil
import time
from pathlib import Path

import pytest

from conftest import load_module, need_python_deps, run_sweep, write_sweep

need_python_deps()
import pandas as pd  # noqa: E402

QUANTITY = "arena.distribute.entity.quantity"
TICKS = 20


def tiny_sweep(tmp_path, name="s", **keys):
    keys.setdefault("params", {QUANTITY: [2, 4]})
    keys.setdefault("seeds", 2)
    keys.setdefault("ticks", TICKS)
    keys.setdefault("out", str(tmp_path / f"{name}-out"))
    return write_sweep(tmp_path / f"{name}.toml", **keys), tmp_path / f"{name}-out"


def read_json(p):
    return json.loads(p.read_text())


def check_table_against_runs(out):
    """The table has one ok row per run, with the run's own summary.json values."""
    df = pd.read_parquet(out / "results.parquet")
    csv = pd.read_csv(out / "results.csv")
    assert len(df) == len(csv) == 4
    for col in ("run", "status", "returncode", "error", "seed", QUANTITY, "ticks", "robots",
                "wall_seconds", "robot_steps_per_second", "summary.essaim_version"):
        assert col in df.columns, col
    assert df["status"].tolist() == ["ok"] * 4
    assert sorted(zip(df[QUANTITY], df["seed"])) == [(2, 1), (2, 2), (4, 1), (4, 2)]
    for _, row in df.iterrows():
        summary = read_json(out / "runs" / row["run"] / "summary.json")
        assert row["seed"] == summary["seed"]
        assert row["ticks"] == summary["ticks"] == TICKS
        assert row["robots"] == summary["robots"] == row[QUANTITY]
        assert row["wall_seconds"] == pytest.approx(summary["wall_seconds"])
        assert row["summary.essaim_version"] == summary["essaim_version"]
        assert json.loads(row["summary.overrides"]) == summary["overrides"]
    return df


def test_local_sweep_then_resume(tmp_path, essaim):
    s, out = tiny_sweep(tmp_path)
    r = run_sweep(s, "-j", "2", essaim=essaim)
    assert r.returncode == 0, r.stderr
    df = check_table_against_runs(out)
    assert df["run"].tolist() == ["quantity=2__seed=1", "quantity=2__seed=2",
                                  "quantity=4__seed=1", "quantity=4__seed=2"]
    assert (out / "sweep.json").is_file()

    # Interrupted sweep: one run folder is gone. A rerun runs that one only.
    mtimes = {k: (out / "runs" / k / "summary.json").stat().st_mtime_ns for k in df["run"]}
    gone = "quantity=4__seed=1"
    for f in (out / "runs" / gone).iterdir():
        f.unlink()
    (out / "runs" / gone).rmdir()
    time.sleep(0.05)
    r = run_sweep(s, "-j", "2", essaim=essaim)
    assert r.returncode == 0, r.stderr
    assert "3 already done, 1 to run" in r.stderr
    for k, m in mtimes.items():
        now = (out / "runs" / k / "summary.json").stat().st_mtime_ns
        assert (now != m) == (k == gone), k
    check_table_against_runs(out)

    # Nothing left to do: nothing runs, the table is rewritten the same.
    r = run_sweep(s, essaim=essaim)
    assert r.returncode == 0 and "4 already done, 0 to run" in r.stderr


def test_failed_runs_are_rows_not_fatal(tmp_path, essaim):
    # A controller error with --strict (exit 1), next to a run that succeeds.
    s, out = tiny_sweep(tmp_path, params={"controllers.ctrl.params.fail": [0, 1]},
                        strict=True, seeds=1)
    r = run_sweep(s, essaim=essaim)
    assert r.returncode == 1, r.stderr
    df = pd.read_parquet(out / "results.parquet").set_index("run")
    assert df.loc["fail=0__seed=1", "status"] == "ok"
    bad = df.loc["fail=1__seed=1"]
    assert bad["status"] == "failed" and bad["returncode"] == 1
    assert "deliberate failure" in bad["error"]
    assert "1 failed" in r.stderr and "deliberate failure" in r.stderr
    # A rerun keeps the run that succeeded and tries the failed one again (essaim may have
    # written a summary.json for it: it is not a finished run).
    r = run_sweep(s, essaim=essaim)
    assert r.returncode == 1 and "1 already done, 1 to run" in r.stderr

    # A --set path that names no element is refused before any run (it used to fail each).
    s, out = tiny_sweep(tmp_path, name="badpath", params={QUANTITY: [2],
                                                          "arena.nosuchthing.attr": [1, 2]},
                        seeds=1)
    r = run_sweep(s, essaim=essaim)
    assert r.returncode == 2, r.stderr
    assert "no element at 'arena.nosuchthing'" in r.stderr and "nothing was run" in r.stderr
    assert not (out / "runs").exists()


def test_dask_cluster_gives_the_same_table(tmp_path, essaim):
    distributed = pytest.importorskip("distributed")
    s, out_local = tiny_sweep(tmp_path, name="local")
    assert run_sweep(s, essaim=essaim).returncode == 0
    s, out = tiny_sweep(tmp_path, name="dask")
    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1,
                                  dashboard_address=None) as cluster:
        r = run_sweep(s, "--scheduler", cluster.scheduler_address, essaim=essaim)
    assert r.returncode == 0, r.stderr
    df = check_table_against_runs(out)
    local = pd.read_parquet(out_local / "results.parquet")
    timing = [c for c in df.columns if "seconds" in c or "per_second" in c
              or c.startswith("summary.us_per")]
    assert df.columns.tolist() == local.columns.tolist()
    pd.testing.assert_frame_equal(df.drop(columns=timing), local.drop(columns=timing))
    # The run folders were written on this side, from what the workers sent back.
    for k in df["run"]:
        assert (out / "runs" / k / "summary.json").is_file()


def test_loop_function_metrics_become_columns(tmp_path, essaim):
    s, out = tiny_sweep(tmp_path, experiment="tiny_loop.argos", params={QUANTITY: [3]},
                        seeds=1)
    r = run_sweep(s, essaim=essaim)
    assert r.returncode == 0, r.stderr
    df = pd.read_parquet(out / "results.parquet")
    metrics = read_json(out / "runs" / df["run"][0] / "metrics.json")
    row = df.iloc[0]
    assert row["trips_per_source.A"] == metrics["trips_per_source"]["A"]
    assert row["trips_per_source.B"] == metrics["trips_per_source"]["B"]
    assert row["trips_total"] == metrics["trips_total"]
    assert row["trips_per_robot_mean"] == pytest.approx(metrics["trips_per_robot_mean"])
    assert not [c for c in df.columns if c.startswith("trips_per_robot.")]
    assert json.loads(row["sources"]) == metrics["sources"]
    assert json.loads(row["dead_robots"]) == metrics["dead_robots"]
    assert row["dead_fraction"] == pytest.approx(metrics["dead_fraction"])
    assert row["first_discovery_tick"] == metrics["first_discovery_tick"]
    assert row["metrics.ticks"] == row["ticks"]  # clashes with summary's: prefixed
    # And the figures can be drawn from it.
    plot = load_module("plot")
    files = plot.make_figures(df, tmp_path / "fig")
    assert len(files) == 8


ZONES = Path(__file__).resolve().parents[1] / "app" / "zones_project"


def zones_sweep(tmp_path, name):
    """A sweep of zones_project (loop functions writing zone_counts.txt), its table taking
    columns from that file."""
    folder = tmp_path / "zones"
    if not folder.exists():
        shutil.copytree(ZONES, folder)
    path = tmp_path / f"{name}.toml"
    path.write_text(f'experiment = "{folder / "zones.argos"}"\nworkdir = "{folder}"\nseeds = 2\nticks = 10\n'
                    f'out = "{tmp_path / (name + "-out")}"\n[params]\n"{QUANTITY}" = [2, 4]\n'
                    '[file_columns]\nlast_tick = "files/zone_counts.txt[tick].last"\n'
                    'inside_mean = "files/zone_counts.txt[inside].mean"\n'
                    'nothing = "files/none.txt[tick].last"\n')
    return path, tmp_path / f"{name}-out"


def check_zone_files(out):
    df = pd.read_parquet(out / "results.parquet")
    assert df["status"].tolist() == ["ok"] * 4
    for _, row in df.iterrows():
        run = out / "runs" / row["run"]
        lines = (run / "files" / "zone_counts.txt").read_text().splitlines()
        assert len(lines) == 11 and all(line.split()[3] == str(row["seed"]) for line in lines[1:])
        inside = [int(line.split()[1]) for line in lines[1:]]
        assert row["last_tick"] == 10 and row["inside_mean"] == pytest.approx(sum(inside) / 10)
        assert pd.isna(row["nothing"])
        assert json.loads(row["summary.files"]) == ["files/zone_counts.txt"]
    return df


def test_each_run_keeps_the_files_it_wrote_and_columns_come_from_them(tmp_path, essaim):
    s, out = zones_sweep(tmp_path, "local")
    r = run_sweep(s, "-j", "2", essaim=essaim)
    assert r.returncode == 0, r.stderr
    local = check_zone_files(out)
    distributed = pytest.importorskip("distributed")
    s, out = zones_sweep(tmp_path, "dask")
    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1,
                                  dashboard_address=None) as cluster:
        r = run_sweep(s, "--scheduler", cluster.scheduler_address, essaim=essaim)
    assert r.returncode == 0, r.stderr
    df = check_zone_files(out)  # the workers sent each run's files back with its outputs
    assert df["inside_mean"].tolist() == local["inside_mean"].tolist()


def test_a_malformed_file_column_is_refused(tmp_path, essaim):
    s, _ = zones_sweep(tmp_path, "bad")
    s.write_text(s.read_text().replace("[tick].last", "[tick].latest", 1))
    r = run_sweep(s, essaim=essaim)
    assert r.returncode == 2, r.stderr
    assert "file_columns.last_tick" in r.stderr and "after the column comes .last" in r.stderr


def test_a_sweep_over_a_path_nobody_reads_is_refused_before_any_run(tmp_path, essaim):
    # A typo used to give rows whose quantity column said 2 and 4 while every run had 4 robots.
    s, out = tiny_sweep(tmp_path, params={"arena.distribute.entity.quantiy": [2, 4]},
                        set={"framework.experiment.lenght": 3})
    r = run_sweep(s, essaim=essaim)
    assert r.returncode == 2, r.stderr
    assert "nothing was run" in r.stderr
    assert "'quantiy' on <entity>; did you mean 'quantity'?" in r.stderr
    assert "did you mean 'length'?" in r.stderr
    assert not (out / "runs").exists()


def test_a_value_that_cannot_load_fails_its_own_runs_only(tmp_path, essaim):
    # 500 robots do not fit in tiny.argos's 3 m x 3 m: that value fails, the other runs.
    s, out = tiny_sweep(tmp_path, name="v", params={QUANTITY: [500, 2]}, seeds=1)
    r = run_sweep(s, essaim=essaim)
    assert r.returncode == 1, r.stderr
    df = pd.read_parquet(out / "results.parquet").set_index("run")
    assert df.loc["quantity=500__seed=1", "status"] == "failed"
    assert "could not place" in df.loc["quantity=500__seed=1", "error"]
    assert df.loc["quantity=2__seed=1", "status"] == "ok"
