"""plot.py on a synthetic sweep table shaped like the foraging one."""
import math
import subprocess
import sys

import pytest

from conftest import SCRIPTS, load_module, need_python_deps

need_python_deps()
import pandas as pd  # noqa: E402

plot = load_module("plot")
FIGURES = ("trips_per_source", "trips_per_robot", "dead_battery", "discovery_time")


def synthetic_table():
    rows = []
    for robots in (10, 20, 30):
        for seed in (1, 2, 3):
            a, b = 10 * robots // 10 + seed, 5 + seed
            rows.append({
                "run": f"quantity={robots}__seed={seed}", "status": "ok", "returncode": 0,
                "error": None, "seed": seed, "arena.distribute.entity.quantity": robots,
                "ticks": 10000, "robots": robots, "trips_total": a + b,
                "trips_per_source.A": a, "trips_per_source.B": b,
                "trips_per_robot_mean": (a + b) / robots, "dead_count": seed,
                "dead_fraction": seed / robots, "first_discovery_tick": 100 * seed,
                # Not every run discovered every source.
                "all_discovered_tick": None if (robots, seed) == (10, 3) else 1000 * seed,
            })
    rows.append({"run": "quantity=40__seed=1", "status": "failed", "returncode": 2,
                 "error": "bad", "seed": 1, "arena.distribute.entity.quantity": 40})
    return pd.DataFrame(rows)


def test_plot_cli_writes_png_and_svg(tmp_path):
    table = tmp_path / "results.parquet"
    synthetic_table().to_parquet(table, index=False)
    r = subprocess.run([sys.executable, str(SCRIPTS / "plot.py"), str(table),
                        "--out", str(tmp_path / "fig")], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    for name in FIGURES:
        png = tmp_path / "fig" / f"{name}.png"
        svg = tmp_path / "fig" / f"{name}.svg"
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        assert png.stat().st_size > 5000
        text = svg.read_text()
        assert "<svg" in text and "mean" in text  # the error-bar note is on the figure


def test_plot_reads_a_sweep_folder_and_csv(tmp_path):
    synthetic_table().to_parquet(tmp_path / "results.parquet", index=False)
    synthetic_table().to_csv(tmp_path / "results.csv", index=False)
    df, where = plot.load_table(tmp_path)
    assert where == tmp_path and len(df) == 10
    csv, _ = plot.load_table(tmp_path / "results.csv")
    assert csv["trips_per_source.A"].equals(df["trips_per_source.A"])
    files = plot.make_figures(csv, tmp_path / "figures", errorbars="ci95")
    assert sorted(p.name for p in files) == \
        sorted(f"{n}.{e}" for n in FIGURES for e in ("png", "svg"))
    assert "95 % CI" in (tmp_path / "figures" / "trips_per_robot.svg").read_text()


def test_error_bars():
    df = synthetic_table()
    df = df[df["status"] == "ok"]
    st = plot.aggregate(df, "robots", df["trips_per_source.B"], "std")
    assert st.loc[10.0, "mean"] == pytest.approx(7.0)
    assert st.loc[10.0, "err"] == pytest.approx(1.0)  # sample std of 6, 7, 8
    ci = plot.aggregate(df, "robots", df["trips_per_source.B"], "ci95")
    assert ci.loc[10.0, "err"] == pytest.approx(4.303 / math.sqrt(3))
    # Missing values (never discovered) are left out of the mean, and counted.
    st = plot.aggregate(df, "robots", df["all_discovered_tick"], "std")
    assert st.loc[10.0, "mean"] == pytest.approx(1500.0)
    assert (st.loc[10.0, "count"], st.loc[10.0, "size"]) == (2, 3)


def test_figures_missing_columns_are_skipped(tmp_path):
    df = synthetic_table()[["run", "status", "seed", "ticks", "robots", "dead_fraction"]]
    files = plot.make_figures(df, tmp_path)
    assert sorted(p.name for p in files) == ["dead_battery.png", "dead_battery.svg"]


def test_hue_and_where(tmp_path):
    df = pd.concat([synthetic_table().assign(**{"controllers.c.params.EPS": e})
                    for e in (0.1, 0.3)], ignore_index=True)
    files = plot.make_figures(df, tmp_path / "hue", hue="controllers.c.params.EPS")
    assert len(files) == 8
    only = plot.parse_where(["controllers.c.params.EPS=0.3"], df)
    assert set(only["controllers.c.params.EPS"]) == {0.3}
