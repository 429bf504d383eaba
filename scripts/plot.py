#!/usr/bin/env python3
"""Figures of essaim runs and sweeps (PNG and SVG).

    plot.py RUN_DIR [--timeseries COLUMN] [--out DIR]
    plot.py SWEEP_DIR --x COLUMN --y COLUMN [--hue COLUMN] [--errorbars std|ci95]
    plot.py SWEEP_DIR --timeseries COLUMN [--hue COLUMN]
    plot.py SWEEP_OUT_OR_TABLE [--x COLUMN] [--errorbars std|ci95] [--where COLUMN=VALUE]...
            [--hue COLUMN]

A run folder (`essaim run --out`): its timeseries.csv, one panel per column over the tick
(or only COLUMN).

A sweep folder (scripts/sweep.py's output) or its results.parquet / .csv table, ok runs only:
with --y, any column over --x, the mean over the runs of each x value (seeds) with error
bars, one line per --hue value; with --timeseries, the runs' time series of one column
(the sweep's timeseries.parquet), overlaid, coloured by --hue. With neither, the report's
chapter-7 figures over the robot count (column `robots`, from summary.json):

  trips_per_source  trips per source, one line per source, and all sources (report fig. 7.2)
  trips_per_robot   trips per robot (fig. 7.3)
  dead_battery      % of robots dead of an empty battery (fig. 7.4)
  discovery_time    ticks until the first source and all sources were discovered

Error bars: --errorbars std (default) is mean +- one sample standard deviation over the
seeds; ci95 is the 95 % confidence interval of the mean (Student t). The choice is written
on every figure. A chapter-7 figure whose columns are not in the table is skipped with a
note. A folder with no table or a column that does not exist is a one-line error naming
what there is (exit 1).
"""
from __future__ import annotations

import argparse
import json
import math
import re
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

# Two-sided 95 % Student t quantiles t(0.975, df), df = 1..30; larger df use the limits below.
T95 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179,
       2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064,
       2.060, 2.056, 2.052, 2.048, 2.045, 2.042]
FORMATS = ("png", "svg")
MARKERS = "osD^vP*Xh<>"


def t95(df: int) -> float:
    if df < 1:
        return math.nan
    if df <= len(T95):
        return T95[df - 1]
    return 2.021 if df <= 40 else 2.000 if df <= 60 else 1.980 if df <= 120 else 1.960


def fail(message: str):
    """A one-line error, exit 1, no traceback."""
    raise SystemExit(f"plot: {message}")


def no_column(name: str, columns, what: str = "the table"):
    fail(f"no column {name!r} in {what}; columns: {', '.join(map(str, columns))}")


def folder_kind(path: Path) -> str:
    """'sweep' (results.parquet), 'run' (timeseries.csv or summary.json), or a one-line error
    saying what the folder holds."""
    if (path / "results.parquet").is_file():
        return "sweep"
    if (path / "timeseries.csv").is_file() or (path / "summary.json").is_file():
        return "run"
    held = sorted(p.name + ("/" if p.is_dir() else "") for p in path.iterdir())
    fail(f"{path}: neither a sweep folder (results.parquet) nor a run folder "
         f"(timeseries.csv, summary.json); it holds: {', '.join(held) if held else 'nothing'}")


def load_table(path: str | Path) -> tuple[pd.DataFrame, Path]:
    """The table, and the folder it came from. `path` is a sweep output folder or a table."""
    path = Path(path)
    if not path.exists():
        fail(f"{path}: no such file or folder")
    if path.is_dir():
        folder_kind(path)
        path = path / "results.parquet"
    if path.suffix == ".parquet":
        df = pd.read_parquet(path)
    elif path.suffix == ".csv":
        df = pd.read_csv(path)
    else:
        raise SystemExit(f"plot: {path}: expected a sweep output folder, .parquet or .csv")
    return df, path.parent


def aggregate(df: pd.DataFrame, x: str, y: pd.Series, errorbars: str) -> pd.DataFrame:
    """Per x value: mean, error half-width, number of runs with a value, number of runs."""
    xs = df[x].astype(float) if pd.api.types.is_numeric_dtype(df[x]) else df[x].astype(str)
    g = pd.DataFrame({"x": xs, "y": pd.to_numeric(y, errors="coerce")})
    stats = g.groupby("x")["y"].agg(["mean", "std", "count", "size"]).sort_index()
    stats["std"] = stats["std"].fillna(0.0)
    if errorbars == "ci95":
        stats["err"] = [t95(int(n) - 1) * s / math.sqrt(n) if n > 1 else 0.0
                        for s, n in zip(stats["std"], stats["count"])]
    else:
        stats["err"] = stats["std"]
    return stats


def errorbar_label(errorbars: str, df: pd.DataFrame, x: str) -> str:
    n = df["seed"].nunique() if "seed" in df else int(df.groupby(x).size().max())
    what = "mean ± 1 std" if errorbars == "std" else "mean ± 95 % CI (Student t)"
    return f"error bars: {what} over {n} seed{'s' if n != 1 else ''}"


def draw(ax, stats: pd.DataFrame, label: str, i: int, style: str = "-",
         annotate_missing: bool = False) -> None:
    ax.errorbar(stats.index, stats["mean"], yerr=stats["err"], label=label, linestyle=style,
                marker=MARKERS[i % len(MARKERS)], markersize=5, capsize=3, linewidth=1.5)
    if annotate_missing:
        for xv, row in stats.iterrows():
            if row["count"] < row["size"] and not math.isnan(row["mean"]):
                ax.annotate(f"{int(row['count'])}/{int(row['size'])}", (xv, row["mean"]),
                            textcoords="offset points", xytext=(4, 6), fontsize=7)


def finish(fig, ax, title: str, xlabel: str, ylabel: str, note: str, out: Path, name: str,
           legend: bool = True, ylim: bool = True) -> list[Path]:
    ax.set_title(title, fontsize=12)
    ax.set_xlabel(xlabel, fontsize=11)
    ax.set_ylabel(ylabel, fontsize=11)
    ax.grid(True, alpha=0.3)
    if ylim:
        ax.set_ylim(bottom=0)
    if legend and ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=9)
    fig.text(0.99, 0.01, note, ha="right", va="bottom", fontsize=8, color="0.35")
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    paths = []
    for fmt in FORMATS:
        p = out / f"{name}.{fmt}"
        fig.savefig(p, dpi=150)
        paths.append(p)
    plt.close(fig)
    return paths


def groups(df: pd.DataFrame, hue: str | None):
    """(label, sub-table) per value of the hue column, or the whole table."""
    if not hue:
        return [(None, df)]
    return [(f"{hue.split('.')[-1]} = {v}", sub) for v, sub in df.groupby(hue, sort=True)]


def make_figures(df: pd.DataFrame, out: str | Path, x: str = "robots", errorbars: str = "std",
                 hue: str | None = None) -> list[Path]:
    """Draw every figure the table has columns for; return the files written."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    if "status" in df:
        df = df[df["status"] == "ok"]
    if df.empty:
        raise SystemExit("plot: no successful run in the table")
    if x not in df:
        no_column(x, df.columns)
    xlabel = "number of robots" if x == "robots" else x
    ticks = sorted(df["ticks"].dropna().unique()) if "ticks" in df else []
    after = f" after {int(ticks[0])} ticks" if len(ticks) == 1 else ""
    note = errorbar_label(errorbars, df, x)
    written: list[Path] = []
    styles = ["-", "--", ":", "-."]

    # Fig. 7.2: trips per source.
    sources = sorted(c for c in df.columns if c.startswith("trips_per_source."))
    if sources:
        fig, ax = plt.subplots(figsize=(7, 4.5))
        k = 0
        for j, (hl, sub) in enumerate(groups(df, hue)):
            for c in sources:
                name = c.split(".", 1)[1]
                draw(ax, aggregate(sub, x, sub[c], errorbars),
                     f"source {name}" + (f", {hl}" if hl else ""), k, styles[j % len(styles)])
                k += 1
            if "trips_total" in sub and not hue:
                st = aggregate(sub, x, sub["trips_total"], errorbars)
                ax.errorbar(st.index, st["mean"], yerr=st["err"], label="all sources",
                            color="0.4", linestyle="--", marker=".", capsize=3, linewidth=1)
        written += finish(fig, ax, f"Trips per source{after}", xlabel, "trips (round trips)",
                          note, out, "trips_per_source")
    else:
        print("plot: no trips_per_source.* columns: trips_per_source skipped", file=sys.stderr)

    # Fig. 7.3: trips per robot.
    if "trips_per_robot_mean" in df or {"trips_total", "robots"} <= set(df.columns):
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for j, (hl, sub) in enumerate(groups(df, hue)):
            y = (sub["trips_per_robot_mean"] if "trips_per_robot_mean" in sub
                 else sub["trips_total"] / sub["robots"])
            draw(ax, aggregate(sub, x, y, errorbars), hl or "trips per robot", j)
        written += finish(fig, ax, f"Trips per robot{after}", xlabel, "trips per robot", note,
                          out, "trips_per_robot", legend=bool(hue))
    else:
        print("plot: no trips_per_robot_mean column: trips_per_robot skipped", file=sys.stderr)

    # Fig. 7.4: robots dead of an empty battery.
    if "dead_fraction" in df or {"dead_count", "robots"} <= set(df.columns):
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for j, (hl, sub) in enumerate(groups(df, hue)):
            y = (sub["dead_fraction"] if "dead_fraction" in sub
                 else sub["dead_count"] / sub["robots"]) * 100.0
            draw(ax, aggregate(sub, x, y, errorbars), hl or "dead robots", j)
        written += finish(fig, ax, f"Robots dead of an empty battery{after}", xlabel,
                          "robots dead of an empty battery (%)", note, out, "dead_battery",
                          legend=bool(hue))
    else:
        print("plot: no dead_fraction column: dead_battery skipped", file=sys.stderr)

    # Source discovery time: first source, all sources. A run where it never happened has
    # no value; the mean is over the runs that have one, marked k/n where k < n.
    # Columns with no value at all (e.g. a sweep where nothing was discovered) are skipped.
    disc = [(c, lab) for c, lab in (("first_discovery_tick", "first source discovered"),
                                    ("all_discovered_tick", "all sources discovered"))
            if c in df and pd.to_numeric(df[c], errors="coerce").notna().any()]
    if disc:
        fig, ax = plt.subplots(figsize=(7, 4.5))
        k = 0
        for j, (hl, sub) in enumerate(groups(df, hue)):
            for c, lab in disc:
                draw(ax, aggregate(sub, x, pd.to_numeric(sub[c], errors="coerce").astype(float), errorbars), lab + (f", {hl}" if hl else ""),
                     k, styles[j % len(styles)], annotate_missing=True)
                k += 1
        written += finish(fig, ax, "Source discovery time", xlabel, "time (ticks)",
                          note + "; k/n: discovered in k of n runs", out, "discovery_time")
    else:
        print("plot: no discovery columns: discovery_time skipped", file=sys.stderr)
    return written


def file_name(*parts: str) -> str:
    return "_".join(re.sub(r"[^A-Za-z0-9.+\-]+", "_", part) for part in parts)


def series_x(ts: pd.DataFrame) -> str:
    """The time axis of a timeseries table: `tick` when there is one, else its first column."""
    return "tick" if "tick" in ts.columns else ts.columns[0]


def plot_run(run_dir: Path, out: Path, column: str | None) -> list[Path]:
    """A run's timeseries.csv: one panel per column (or only `column`) over the tick."""
    csv = run_dir / "timeseries.csv"
    if not csv.is_file():
        held = ", ".join(sorted(p.name for p in run_dir.iterdir()))
        fail(f"{run_dir}: no timeseries.csv (the experiment's loop functions write it with "
             f"experiment.timeseries); the folder holds: {held}")
    try:
        ts = pd.read_csv(csv)
    except (ValueError, OSError) as e:
        fail(f"{csv}: {e}")
    x = series_x(ts)
    names = [c for c in ts.columns if c != x and pd.api.types.is_numeric_dtype(ts[c])]
    if column is not None:
        if column not in names:
            no_column(column, names, str(csv))
        names = [column]
    if not names:
        fail(f"{csv}: no numeric column to draw besides {x!r}")
    out.mkdir(parents=True, exist_ok=True)
    fig, axes = plt.subplots(len(names), 1, figsize=(7, 1.2 + 1.8 * len(names)), sharex=True,
                             squeeze=False)
    for ax, name in zip(axes[:, 0], names):
        ax.plot(ts[x], ts[name], linewidth=1.2)
        ax.set_ylabel(name, fontsize=9)
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel(x, fontsize=11)
    return finish(fig, axes[0, 0], f"{run_dir.resolve().name}: time series", "", names[0],
                  str(csv), out, file_name("timeseries", *([column] if column else [])),
                  legend=False, ylim=False)


def plot_column(df: pd.DataFrame, out: Path, x: str, y: str, hue: str | None,
                errorbars: str) -> list[Path]:
    """Any column of a sweep over another: mean and error bars over the runs of each x."""
    for name in (x, y):
        if name not in df:
            no_column(name, df.columns)
    if not pd.api.types.is_numeric_dtype(df[y]):
        fail(f"column {y!r} is not numeric; numeric columns: "
             + ", ".join(c for c in df.columns if pd.api.types.is_numeric_dtype(df[c])))
    out.mkdir(parents=True, exist_ok=True)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for j, (hl, sub) in enumerate(groups(df, hue)):
        draw(ax, aggregate(sub, x, sub[y], errorbars), hl or y, j)
    return finish(fig, ax, f"{y} by {x}", x, y, errorbar_label(errorbars, df, x), out,
                  file_name(y, "by", x), legend=bool(hue), ylim=False)


def sweep_timeseries(table_dir: Path, df: pd.DataFrame) -> pd.DataFrame:
    """The sweep's timeseries.parquet, or (older sweeps) its ok runs' timeseries.csv."""
    path = table_dir / "timeseries.parquet"
    if path.is_file():
        return pd.read_parquet(path)
    frames = []
    for run in df.get("run", []):
        csv = table_dir / "runs" / str(run) / "timeseries.csv"
        if csv.is_file():
            frames.append(pd.read_csv(csv).assign(run=run))
    if not frames:
        fail(f"{table_dir}: no timeseries.parquet and no run with a timeseries.csv "
             "(the experiment's loop functions write none)")
    return pd.concat(frames, ignore_index=True)


def plot_timeseries(df: pd.DataFrame, table_dir: Path, out: Path, column: str,
                    hue: str | None) -> list[Path]:
    """One line per run of the sweep's time series `column`, coloured by the hue value."""
    ts = sweep_timeseries(table_dir, df)
    if column not in ts:
        no_column(column, [c for c in ts.columns if c != "run"], "the runs' time series")
    ts = ts[ts["run"].isin(set(df["run"]))]
    x = series_x(ts.drop(columns=[c for c in ts.columns if c in df.columns and c != "tick"]))
    hue_of = dict(zip(df["run"], df[hue])) if hue else {}
    colours = {v: f"C{i % 10}" for i, v in enumerate(sorted(set(hue_of.values()), key=str))}
    out.mkdir(parents=True, exist_ok=True)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    labelled = set()
    for run, sub in ts.groupby("run", sort=False):
        v = hue_of.get(run)
        label = f"{hue.split('.')[-1]} = {v}" if hue and v not in labelled else None
        labelled.add(v)
        ax.plot(sub[x], sub[column], color=colours.get(v, "C0"), alpha=0.6, linewidth=1,
                label=label)
    note = f"{ts['run'].nunique()} runs, one line each"
    return finish(fig, ax, f"{column} over time", x, column, note, out,
                  file_name("timeseries", column), legend=bool(hue), ylim=False)


def parse_where(items: list[str], df: pd.DataFrame) -> pd.DataFrame:
    for item in items:
        col, sep, val = item.partition("=")
        if not sep:
            fail(f"--where {item!r}: expected COLUMN=VALUE")
        if col not in df:
            no_column(col, df.columns)
        s = df[col]
        if pd.api.types.is_numeric_dtype(s):
            df = df[s.astype(float) == float(val)]
        else:
            df = df[s.astype(str) == val]
    return df


def warn_other_params(df: pd.DataFrame, table_dir: Path, x: str, hue: str | None,
                      where: list[str]) -> None:
    """Say so when another swept parameter varies and is neither --hue nor --where."""
    manifest = table_dir / "sweep.json"
    try:
        params = json.loads(manifest.read_text()).get("params", {})
    except (OSError, ValueError):
        return
    fixed = {w.partition("=")[0] for w in where}
    for p in params:
        if p in df and p not in fixed and p != hue and df[p].nunique() > 1:
            if x == "robots" and p == "arena.distribute.entity.quantity":
                continue
            print(f"plot: note: {p} varies in this table and is averaged over; use "
                  f"--hue {p} or --where {p}=VALUE", file=sys.stderr)


def parse_args(argv):
    ap = argparse.ArgumentParser(prog="plot.py", description=__doc__.split("\n\n")[0])
    ap.add_argument("table", help="a run folder, a sweep output folder, or a sweep's "
                                  "results.parquet / .csv")
    ap.add_argument("--out", help="folder for the figures (default: <folder>/figures)")
    ap.add_argument("--x", help="x-axis column (default: robots)")
    ap.add_argument("--y", metavar="COLUMN", help="draw this column over --x (mean and error "
                                                  "bars over the runs of each x)")
    ap.add_argument("--timeseries", metavar="COLUMN",
                    help="draw this time-series column, one line per run")
    ap.add_argument("--errorbars", choices=("std", "ci95"), default="std",
                    help="std: mean ± 1 standard deviation (default); ci95: 95%% CI of the mean")
    ap.add_argument("--where", action="append", default=[], metavar="COLUMN=VALUE",
                    help="keep only the rows where COLUMN equals VALUE (repeatable)")
    ap.add_argument("--hue", metavar="COLUMN", help="one line per value of this column")
    return ap.parse_args(argv)


def main(argv=None) -> int:
    args = parse_args(argv)
    path = Path(args.table)
    if path.is_dir() and folder_kind(path) == "run":
        written = plot_run(path, Path(args.out) if args.out else path / "figures",
                           args.timeseries)
    else:
        written = plot_sweep(args)
    for p in written:
        print(p)
    if not written:
        print("plot: the table has none of the foraging metrics columns: no figure "
              "(draw any column with --x COLUMN --y COLUMN)", file=sys.stderr)
        return 1
    return 0


def plot_sweep(args) -> list[Path]:
    df, table_dir = load_table(args.table)
    df = parse_where(args.where, df)
    if args.hue and args.hue not in df:
        no_column(args.hue, df.columns)
    x = args.x or "robots"
    warn_other_params(df, table_dir, x, args.hue, args.where)
    out = Path(args.out) if args.out else table_dir / "figures"
    if "status" in df:
        df = df[df["status"] == "ok"]
    if (args.y or args.timeseries) and df.empty:
        fail("no successful run in the table")
    if args.timeseries:
        return plot_timeseries(df, table_dir, out, args.timeseries, args.hue)
    if args.y:
        return plot_column(df, out, x, args.y, args.hue, args.errorbars)
    return make_figures(df, out, x=x, errorbars=args.errorbars, hue=args.hue)


if __name__ == "__main__":
    sys.exit(main())
