#!/usr/bin/env python3
"""Figures of docs/foraging.md, from sweep tables (scripts/sweep.py).

    plot_foraging.py shares DRAIN_SWEEP... [--out DIR]
    plot_foraging.py epsilon EPSILON_SWEEP [--out DIR]

shares: each source's share of all trips against the robot count, one panel per sweep (the
sweeps of scripts/sweeps/sources_drain_*.toml), median over seeds with the min-max range as a
band; the panel is titled by the sweep's BATT_BY_STEP. Also prints the medians.

epsilon: the study of scripts/sweeps/epsilon.toml: trips per robot and source A's share of the
trips against epsilon, one line per robot count (median over seeds, interquartile band). Also
prints the medians and, per robot count, the epsilon with the most trips.

Figures are written as PNG and SVG.
"""
from __future__ import annotations

import argparse
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

EPS = "controllers.foraging.params.EPSILONGREED"
FORMATS = ("png", "svg")


def load(folder: str) -> tuple[pd.DataFrame, dict]:
    """The ok runs of a sweep and its sweep.json."""
    path = Path(folder)
    df = pd.read_parquet(path / "results.parquet")
    sweep = json.loads((path / "sweep.json").read_text())
    ok = df[df.status == "ok"].copy()
    if ok.empty:
        raise SystemExit(f"plot_foraging: {folder}: no successful run")
    return ok, sweep


def source_names(df: pd.DataFrame) -> list[str]:
    return sorted(c.split(".", 1)[1] for c in df.columns if c.startswith("trips_per_source."))


def with_shares(df: pd.DataFrame) -> pd.DataFrame:
    total = df["trips_total"].where(df["trips_total"] > 0)
    for name in source_names(df):
        df["share_" + name] = 100.0 * df["trips_per_source." + name] / total
    return df


def drain_of(sweep: dict) -> str:
    text = json.dumps(sweep)
    key = '"controllers.foraging.params.BATT_BY_STEP": '
    at = text.find(key)
    return text[at + len(key):].split(",")[0].split("}")[0].strip('" ') if at >= 0 else "?"


def save(fig, out: Path, name: str) -> None:
    out.mkdir(parents=True, exist_ok=True)
    for fmt in FORMATS:
        fig.savefig(out / f"{name}.{fmt}", dpi=110, bbox_inches="tight")
    plt.close(fig)
    print(f"plot_foraging: wrote {out / name}.png/.svg")


def shares(folders: list[str], out: Path) -> None:
    fig, axes = plt.subplots(1, len(folders), figsize=(5.2 * len(folders), 4), sharey=True,
                             squeeze=False)
    for ax, folder in zip(axes[0], folders):
        df, sweep = load(folder)
        df = with_shares(df)
        drain = drain_of(sweep)
        for name in source_names(df):
            g = df.groupby("robots")["share_" + name]
            med, lo, hi = g.median(), g.min(), g.max()
            ax.plot(med.index, med.values, marker="o", label=f"source {name}")
            ax.fill_between(med.index, lo.values, hi.values, alpha=0.15)
            for n, v in med.items():
                print(f"drain {drain}: {n} robots: {name} {v:.1f} % of trips (median)")
        tpr = df.groupby("robots")["trips_per_robot_mean"].median()
        print(f"drain {drain}: trips per robot (median) " +
              ", ".join(f"{n}: {v:.2f}" for n, v in tpr.items()))
        ax.set_title(f"drain {drain} per tick (BATT_BY_STEP = {drain})")
        ax.set_xlabel("robots")
        ax.set_xticks(sorted(df["robots"].unique()))
        ax.set_ylim(0, 100)
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("share of all trips (%)")
    axes[0][0].legend()
    fig.suptitle("Source shares, sources known (median over seeds, band: min-max)")
    save(fig, out, "source_shares")


def epsilon(folder: str, out: Path) -> None:
    df, _ = load(folder)
    df = with_shares(df)
    fig, (left, right) = plt.subplots(1, 2, figsize=(10.4, 4))
    for n, g in df.groupby("robots"):
        for ax, col in ((left, "trips_per_robot_mean"), (right, "share_A")):
            q = g.groupby(EPS)[col].quantile([0.25, 0.5, 0.75]).unstack()
            ax.plot(q.index, q[0.5], marker="o", label=f"{n} robots")
            ax.fill_between(q.index, q[0.25], q[0.75], alpha=0.15)
        med = g.groupby(EPS)["trips_per_robot_mean"].median()
        share = g.groupby(EPS)["share_A"].median()
        print(f"{n} robots: trips per robot (median) " +
              ", ".join(f"eps {e:g}: {v:.2f}" for e, v in med.items()))
        print(f"{n} robots: A's share (median) " +
              ", ".join(f"eps {e:g}: {v:.0f} %" for e, v in share.items()))
        print(f"{n} robots: most trips at eps {med.idxmax():g}")
    left.set_ylabel("trips per robot")
    right.set_ylabel("source A's share of trips (%)")
    for ax in (left, right):
        ax.set_xlabel("epsilon (EPSILONGREED)")
        ax.grid(alpha=0.3)
    left.legend()
    fig.suptitle("Epsilon study, sources known, 10 000 ticks, the arena's drain "
                 "(median over seeds, band: IQR)")
    save(fig, out, "epsilon")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("figure", choices=("shares", "epsilon"))
    ap.add_argument("sweeps", nargs="+", help="sweep output folders")
    ap.add_argument("--out", default="docs/img/foraging", help="folder for the figures")
    args = ap.parse_args()
    if args.figure == "shares":
        shares(args.sweeps, Path(args.out))
    else:
        if len(args.sweeps) != 1:
            ap.error("epsilon takes one sweep folder")
        epsilon(args.sweeps[0], Path(args.out))


if __name__ == "__main__":
    main()
