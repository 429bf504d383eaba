"""sweep.py without the simulator: sweep files, run keys, the table, failure and Ctrl-C paths
(with stand-in binaries)."""
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conftest import DATA, SCRIPTS, load_module, need_python_deps, run_sweep, write_sweep

need_python_deps()
sweep = load_module("sweep")

# The metrics.json schema of the foraging loop functions.
FORAGING_METRICS = {
    "ticks": 10000, "robots": 30, "trips_total": 123,
    "trips_per_source": {"A": 80, "B": 30, "C": 13},
    "trips_per_robot": {"fb0": 4, "fb1": 0}, "trips_per_robot_mean": 4.1,
    "sources": [{"name": "A", "x": -2.5, "y": 0.0, "radius": 0.5, "discovered_tick": 120,
                 "discovered_by": "fb3", "trips": 80}],
    "discovered_count": 3, "first_discovery_tick": 120, "all_discovered_tick": 900,
    "dead_robots": [{"robot": "fb4", "tick": 5012}], "dead_count": 1, "dead_fraction": 0.0333,
}
SUMMARY = {
    "essaim_version": "0.1.0", "experiment": "arenas/foraging.argos", "experiment_sha256": "ab",
    "overrides": ["a.b=1"], "seed": 7, "ticks": 10000, "ticks_per_second": 10, "robots": 30,
    "threads": 1, "wall_seconds": 12.3, "robot_steps_per_second": 24390.2,
    "us_per_robot_step": 41.0, "stage_seconds": {"act": 0.1, "control": 8.0},
    "controller_errors": [{"robot": "fb3", "tick": 120, "message": "x"}],
    "outputs": ["summary.json"], "finished_by": "length",
}


def test_ranges_include_stop_and_have_no_float_noise():
    assert sweep.expand_values("p", {"start": 10, "stop": 100, "step": 10}) == list(range(10, 101, 10))
    assert sweep.expand_values("p", {"start": 0.1, "stop": 0.5, "step": 0.1}) == [0.1, 0.2, 0.3, 0.4, 0.5]
    assert sweep.expand_values("p", {"start": 5, "stop": 1, "step": -2}) == [5, 3, 1]
    assert sweep.expand_values("p", {"start": 1, "stop": 3}) == [1, 2, 3]
    assert sweep.expand_values("p", [1, "x", True]) == [1, "x", True]
    assert sweep.expand_values("p", 0.3) == [0.3]
    for bad in ({"start": 1, "stop": 3, "step": 0}, {"start": 1, "stop": 3, "step": -1},
                {"start": 1}, {"start": 1, "stop": 2, "num": 3}, [], [[1]]):
        with pytest.raises(sweep.SweepError):
            sweep.expand_values("p", bad)


def test_set_values_are_attribute_text():
    assert [sweep.format_value(v) for v in (10, 0.1, 10.0, True, "1,2,0")] == \
        ["10", "0.1", "10.0", "true", "1,2,0"]


def test_run_keys_are_readable_stable_and_distinct():
    names = sweep.short_names(["arena.distribute.entity.quantity",
                               "controllers.foraging.params.EPSILONGREED"])
    assert names == {"arena.distribute.entity.quantity": "quantity",
                     "controllers.foraging.params.EPSILONGREED": "EPSILONGREED"}
    point = {"arena.distribute.entity.quantity": 30,
             "controllers.foraging.params.EPSILONGREED": 0.1}
    assert sweep.run_key(point, 2, names) == "quantity=30__EPSILONGREED=0.1__seed=2"
    # Same last segment: longer suffixes tell them apart.
    names = sweep.short_names(["arena.distribute.entity.quantity",
                               "arena.distribute[1].entity.quantity"])
    assert len(set(names.values())) == 2
    # Characters unfit for a folder name are replaced, and a hash keeps keys distinct.
    k1 = sweep.run_key({"a.b.pos": "1,2"}, 1, {"a.b.pos": "pos"})
    k2 = sweep.run_key({"a.b.pos": "1 2"}, 1, {"a.b.pos": "pos"})
    assert k1 != k2 and "/" not in k1 and "," not in k1 and " " not in k2


def test_flatten_metrics_follows_the_schema():
    row = sweep.flatten_metrics(FORAGING_METRICS)
    assert row["trips_per_source.A"] == 80 and row["trips_per_source.C"] == 13
    assert not any(k.startswith("trips_per_robot.") or k == "trips_per_robot" for k in row)
    assert row["trips_per_robot_mean"] == 4.1
    assert json.loads(row["sources"])[0]["discovered_by"] == "fb3"
    assert json.loads(row["dead_robots"]) == [{"robot": "fb4", "tick": 5012}]
    assert row["all_discovered_tick"] == 900 and row["dead_fraction"] == 0.0333


def test_flatten_summary_keeps_key_columns_unprefixed():
    row = sweep.flatten_summary(SUMMARY)
    for k in ("seed", "ticks", "robots", "wall_seconds", "robot_steps_per_second"):
        assert row[k] == SUMMARY[k]
    assert row["summary.experiment"] == "arenas/foraging.argos"
    assert row["summary.stage_seconds.control"] == 8.0
    assert json.loads(row["summary.overrides"]) == ["a.b=1"]
    assert row["controller_error_count"] == 1


def test_table_types_survive_missing_values(tmp_path):
    rows = [{"run": "a", "status": "ok", "returncode": 0, "error": None, "seed": 1, "n": 3,
             "x": 0.5, "first_discovery_tick": 5},
            {"run": "b", "status": "failed", "returncode": 2, "error": "bad", "seed": 2, "n": 4}]
    df = sweep.make_table(rows)
    assert list(df.columns[:5]) == ["run", "status", "returncode", "error", "seed"]
    assert str(df["first_discovery_tick"].dtype) == "Int64"
    assert df["first_discovery_tick"].isna().tolist() == [False, True]
    sweep.write_table(df, tmp_path)
    import pandas as pd
    back = pd.read_parquet(tmp_path / "results.parquet")
    assert back["error"].tolist()[1] == "bad" and back["n"].tolist() == [3, 4]
    assert len(pd.read_csv(tmp_path / "results.csv")) == 2


def test_bad_sweep_files_exit_2(tmp_path):
    bad = write_sweep(tmp_path / "bad.toml", seeds=2, colour="red")
    r = run_sweep(bad, env={"ESSAIM": "/bin/true"})
    assert r.returncode == 2 and "unknown key" in r.stderr and "colour" in r.stderr
    missing = write_sweep(tmp_path / "m.toml", experiment="nope.argos")
    r = run_sweep(missing, env={"ESSAIM": "/bin/true"})
    assert r.returncode == 2 and "nope.argos" in r.stderr
    both = write_sweep(tmp_path / "b.toml", params={"a.b.c": [1, 2]}, set={"a.b.c": 3})
    r = run_sweep(both, env={"ESSAIM": "/bin/true"})
    assert r.returncode == 2 and "both" in r.stderr


def test_missing_binary_exits_2(tmp_path):
    s = write_sweep(tmp_path / "s.toml")
    r = run_sweep(s, "--essaim", tmp_path / "no-such-essaim")
    assert r.returncode == 2 and "no-such-essaim" in r.stderr


def test_dry_run_prints_the_command_lines(tmp_path):
    s = write_sweep(tmp_path / "s.toml", ticks=20, seeds=[3, 5], out=str(tmp_path / "out"),
                    params={"arena.distribute.entity.quantity": [2, 4]},
                    set={"controllers.ctrl.params.speed": 7})
    r = run_sweep(s, "--dry-run", env={"ESSAIM": "/bin/true"})
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    assert len(lines) == 4
    first = lines[0].split()
    assert first[:3] == ["/bin/true", "run", str(DATA / "tiny.argos")]
    assert "--quiet" in first and first[first.index("--seed") + 1] == "3"
    assert first[first.index("--ticks") + 1] == "20"
    assert "controllers.ctrl.params.speed=7" in first
    assert "arena.distribute.entity.quantity=2" in first
    assert first[-2:] == ["--out", str(tmp_path / "out" / "runs" / "quantity=2__seed=3")]
    assert not (tmp_path / "out").exists()


def test_a_run_without_summary_is_a_failed_row(tmp_path):
    # /bin/true exits 0 but writes nothing: every run is reported failed, none is fatal.
    s = write_sweep(tmp_path / "s.toml", seeds=2, out=str(tmp_path / "out"))
    r = run_sweep(s, "-j", "2", env={"ESSAIM": "/bin/true"})
    assert r.returncode == 1
    assert "2 failed" in r.stderr and "without writing summary.json" in r.stderr
    import pandas as pd
    df = pd.read_parquet(tmp_path / "out" / "results.parquet")
    assert df["status"].tolist() == ["failed", "failed"]


def start_slow_sweep(tmp_path, seeds):
    """A sweep at -j 2 over a stand-in essaim that records its pid in its --out folder and
    sleeps for an hour (far longer than any guard below, so that a sweep that waited for its
    runs instead of killing them fails); returns the sweep process once both runs have
    started, and their pids."""
    fake = tmp_path / "slow-essaim"
    fake.write_text('#!/bin/sh\n[ "$1" = check ] && exit 0\nfor last; do :; done\necho $$ > "$last/pid"\nexec sleep 3600\n')
    fake.chmod(0o755)
    s = write_sweep(tmp_path / "s.toml", seeds=seeds, out=str(tmp_path / "out"))
    p = subprocess.Popen([sys.executable, str(SCRIPTS / "sweep.py"), str(s), "-j", "2",
                          "--essaim", str(fake), "--no-progress"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    pids = []
    deadline = time.time() + 120  # a hang guard: sweep.py starts in about a second
    while len(pids) < 2 and time.time() < deadline:
        time.sleep(0.1)
        pids = [int(f.read_text()) for f in (tmp_path / "out" / "runs").glob("*/pid")
                if f.read_text().strip()]
    assert len(pids) == 2, "the stand-in runs did not start"
    return p, pids


def test_ctrl_c_kills_the_runs_and_exits_130(tmp_path):
    p, pids = start_slow_sweep(tmp_path, seeds=4)
    t0 = time.time()
    p.send_signal(signal.SIGINT)
    _, err = p.communicate(timeout=120)  # a hang guard; the runs would sleep an hour
    print(f"sweep interrupted in {time.time() - t0:.1f} s")
    assert p.returncode == 130, err
    assert "interrupted" in err
    for pid in pids:
        with pytest.raises(ProcessLookupError):
            os.kill(pid, 0)


def test_only_successful_runs_count_as_finished(tmp_path):
    argv = ["run", "x.argos", "--quiet", "--seed", "1"]
    d = tmp_path / "run"
    d.mkdir()
    assert not sweep.finished(d, argv)
    (d / "summary.json").write_text("{not json")
    assert not sweep.finished(d, argv)
    (d / sweep.RUN_RECORD).write_text(json.dumps({"argv": argv, "returncode": 0}))
    for status, done in (("ok", True), ("controller_error", True), ("failed", False),
                         ("interrupted", False)):
        (d / "summary.json").write_text(json.dumps({"seed": 1, "status": status,
                                                    "controller_errors": []}))
        assert sweep.finished(d, argv) == done, status
    (d / "summary.json").write_text(json.dumps({"seed": 1, "controller_errors": [{"robot": "a"}]}))
    assert sweep.finished(d, argv) and not sweep.finished(d, argv, strict=True)
    (d / "summary.json").write_text(json.dumps({"seed": 1}))
    assert sweep.finished(d, argv)
    # Without the sweep's marker (an orphan of a killed sweep wrote it): redone.
    (d / sweep.RUN_RECORD).unlink()
    assert not sweep.finished(d, argv)
    (d / sweep.RUN_RECORD).write_text(json.dumps({"argv": argv, "returncode": 0}))
    assert not sweep.finished(d, argv + ["--ticks", "5"])  # made by another command line
    (d / sweep.RUN_RECORD).write_text(json.dumps({"argv": argv, "returncode": 1}))
    assert not sweep.finished(d, argv)


def test_error_is_the_stderr_tail_without_lua_tracebacks():
    err = ("robot fb0: tiny.lua:13: boom\nstack traceback:\n\t[C]: in function 'error'\n"
           "\ttiny.lua:13: in function 'step'\n\nessaim run: robot fb0: tiny.lua:13: boom\n"
           "stack traceback:\n\t[C]: in function 'error'\n")
    assert sweep.stderr_tail(err) == "robot fb0: tiny.lua:13: boom\nessaim run: robot fb0: tiny.lua:13: boom"
    assert sweep.stderr_tail("\n".join(f"l{i}" for i in range(9))) == "l4\nl5\nl6\nl7\nl8"


def _alive(pid: int) -> bool:
    """Running (a zombie waiting for its reaper counts as dead)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="PR_SET_PDEATHSIG is Linux's")
def test_runs_die_with_a_killed_sweep(tmp_path):
    p, pids = start_slow_sweep(tmp_path, seeds=2)
    p.kill()  # SIGKILL: the sweep cannot clean up
    p.communicate(timeout=20)
    deadline = time.time() + 120  # a hang guard; the runs would sleep an hour
    while any(_alive(pid) for pid in pids) and time.time() < deadline:
        time.sleep(0.1)
    assert not any(_alive(pid) for pid in pids)


def test_without_essaim_on_path_the_checkouts_build_is_used(tmp_path, monkeypatch):
    """Tutorial §3 from a shell with no `essaim` on PATH: the checkout's build/essaim runs."""
    built = tmp_path / "build" / "essaim"
    built.parent.mkdir()
    built.write_text("#!/bin/sh\n")
    built.chmod(0o755)
    s = write_sweep(tmp_path / "s.toml", seeds=1)
    monkeypatch.setenv("PATH", str(tmp_path / "empty"))
    monkeypatch.delenv("ESSAIM", raising=False)
    monkeypatch.setattr(sweep, "PROJECT_ESSAIM", built)
    assert sweep.resolve_essaim(None, sweep.load_sweep(s), remote=False) == str(built)
    built.unlink()  # not built either: the message says what to do
    with pytest.raises(sweep.SweepError, match="is not on PATH and .*build/essaim is not built: run "
                                               "bash scripts/setup.sh"):
        sweep.resolve_essaim(None, sweep.load_sweep(s), remote=False)
