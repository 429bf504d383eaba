"""plot.py on any run or sweep: a run's time series, any column of a sweep over another,
the runs' time series overlaid, and one-line errors naming what exists; the sweep's
timeseries.parquet."""
import contextlib
import io
import shutil
import subprocess
import sys

import pytest

from conftest import DATA, SCRIPTS, load_module, need_python_deps, run_sweep

need_python_deps()
import pandas as pd  # noqa: E402

LOOP = """
local east = 0
function post_step()
  for _, r in ipairs(experiment.robots) do
    local x = r:position()
    if x > 0 then east = east + 1 end
  end
  experiment.timeseries({{"tick", experiment.tick}, {"east", east}, {"half", experiment.tick / 2}})
end
"""


PLOT = load_module("plot")


def plot(*args):
    """plot.py's main in this process (one interpreter start per call would cost seconds),
    with its exit status and stderr as a subprocess would give them."""
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        try:
            rc = PLOT.main([str(a) for a in args])
        except SystemExit as e:  # what the interpreter does with it
            if isinstance(e.code, str):
                print(e.code, file=err)
            rc = 1 if isinstance(e.code, str) else e.code
    return subprocess.CompletedProcess(args, rc, "", err.getvalue())


def test_errors_leave_no_traceback(tmp_path):
    r = subprocess.run([sys.executable, str(SCRIPTS / "plot.py"), str(tmp_path)],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 1 and r.stderr.strip().splitlines() == [
        f"plot: {tmp_path}: neither a sweep folder (results.parquet) nor a run folder "
        "(timeseries.csv, summary.json); it holds: nothing"]


def one_line_error(r, *needles):
    assert r.returncode == 1, r.stderr
    assert "Traceback" not in r.stderr, r.stderr
    last = r.stderr.strip().splitlines()[-1]  # notes may come before it
    assert last.startswith("plot: "), r.stderr
    for n in needles:
        assert n in last, r.stderr


@pytest.fixture(scope="module")
def swept(tmp_path_factory, essaim):
    """A sweep of 2 robot counts x 2 seeds, 12 ticks, with loop functions writing a time
    series."""
    root = tmp_path_factory.mktemp("ts")
    shutil.copy(DATA / "tiny.lua", root)
    (root / "loop.lua").write_text(LOOP)
    (root / "x.argos").write_text((DATA / "tiny_loop.argos").read_text()
                                  .replace('script="tiny_loop.lua"', 'script="loop.lua"'))
    (root / "s.toml").write_text('experiment = "x.argos"\nworkdir = "."\nout = "out"\n'
                                 'ticks = 12\nseeds = 2\n'
                                 '[params]\n"arena.distribute.entity.quantity" = [2, 3]\n')
    r = run_sweep(root / "s.toml", essaim=essaim)
    assert r.returncode == 0, r.stderr
    return root / "out"


def test_a_sweep_writes_one_timeseries_table_for_all_runs(swept):
    ts = pd.read_parquet(swept / "timeseries.parquet")
    results = pd.read_parquet(swept / "results.parquet")
    assert list(ts.columns) == ["run", "seed", "arena.distribute.entity.quantity",
                                "tick", "east", "half"]
    assert sorted(ts["run"].unique()) == sorted(results["run"])
    for run in results["run"]:
        own = pd.read_csv(swept / "runs" / run / "timeseries.csv")
        mine = ts[ts["run"] == run].reset_index(drop=True)
        assert mine["tick"].tolist() == own["tick"].tolist() == list(range(1, 13))
        assert mine["east"].tolist() == own["east"].tolist()


def test_plot_a_run_folder_draws_its_time_series(swept, tmp_path):
    run = next((swept / "runs").iterdir())
    r = plot(run, "--out", tmp_path / "f")
    assert r.returncode == 0, r.stderr
    png = tmp_path / "f" / "timeseries.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "east" in (tmp_path / "f" / "timeseries.svg").read_text()
    r = plot(run, "--timeseries", "half", "--out", tmp_path / "f")
    assert r.returncode == 0 and (tmp_path / "f" / "timeseries_half.png").is_file()
    one_line_error(plot(run, "--timeseries", "west"), "no column 'west'", "east, half")


def test_plot_any_column_of_a_sweep_with_mean_and_spread(swept, tmp_path):
    r = plot(swept, "--x", "seed", "--y", "summary.robots_alive", "--out", tmp_path)
    assert r.returncode == 0, r.stderr
    svg = (tmp_path / "summary.robots_alive_by_seed.svg").read_text()
    assert "mean ± 1 std over 2 seeds" in svg
    r = plot(swept, "--x", "robots", "--y", "summary.lua_memory_bytes", "--hue", "seed",
             "--errorbars", "ci95", "--out", tmp_path)
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "summary.lua_memory_bytes_by_robots.png").is_file()
    one_line_error(plot(swept, "--x", "seed", "--y", "robots_alive"),
                   "no column 'robots_alive'", "summary.robots_alive")
    one_line_error(plot(swept, "--x", "nope", "--y", "robots"), "no column 'nope'", "seed")


def test_plot_the_runs_time_series_overlaid(swept, tmp_path):
    r = plot(swept, "--timeseries", "east", "--hue", "robots", "--out", tmp_path)
    assert r.returncode == 0, r.stderr
    svg = (tmp_path / "timeseries_east.svg").read_text()
    assert "4 runs, one line each" in svg and "robots = 2" in svg
    one_line_error(plot(swept, "--timeseries", "west"), "no column 'west'", "east")


def test_folders_without_a_table_are_one_line_errors(tmp_path):
    empty = tmp_path / "empty"
    empty.mkdir()
    one_line_error(plot(empty), "neither a sweep folder", "it holds: nothing")
    (tmp_path / "other").mkdir()
    (tmp_path / "other" / "notes.txt").write_text("x")
    one_line_error(plot(tmp_path / "other"), "it holds: notes.txt")
    one_line_error(plot(tmp_path / "missing"), "no such file or folder")
    run = tmp_path / "run"
    run.mkdir()
    (run / "summary.json").write_text("{}")
    one_line_error(plot(run), "no timeseries.csv", "the folder holds: summary.json")


def test_write_timeseries_skips_runs_without_one(tmp_path):
    sweep = load_module("sweep")
    runs = [sweep.Run("a=1__seed=1", {"x.y.a": 1}, 1), sweep.Run("a=2__seed=1", {"x.y.a": 2}, 1)]
    (tmp_path / "runs" / runs[0].key).mkdir(parents=True)
    (tmp_path / "runs" / runs[0].key / "timeseries.csv").write_text("tick,v\n1,2.5\n2,3\n")
    rows = [{"run": r.key, "status": "ok"} for r in runs]
    assert sweep.write_timeseries(runs, rows, tmp_path)
    ts = pd.read_parquet(tmp_path / "timeseries.parquet")
    assert ts.to_dict("list") == {"run": ["a=1__seed=1"] * 2, "seed": [1, 1], "x.y.a": [1, 1],
                                  "tick": [1, 2], "v": [2.5, 3.0]}
    assert not sweep.write_timeseries(runs[1:], rows[1:], tmp_path / "none")
