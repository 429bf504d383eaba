#!/usr/bin/env python3
"""Soak run: the foraging experiment for a million ticks with a recording, memory sampled by
essaim itself (`run --memory-log N`: resident set and Lua bytes every N ticks). Writes a
figure and a numbers table (bench/soak-memory.png, bench/soak.md) and exits 1 when memory
did not stay flat. Not a test: the full run takes about an hour on one core.

    tools/soak.py [--ticks 1000000] [--every 10000] [--out runs/soak] [--bench-dir bench]
"""
import argparse
import csv
import json
import os
import pathlib
import platform
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
# Flat: after warm-up, the last tenth of the run holds no more than this much more memory
# than the window just after warm-up.
MAX_GROWTH = 0.05


def window_mean(values, lo, hi):
    part = values[lo:hi] or values[-1:]
    return sum(part) / len(part)


def growth(values):
    """Relative growth from the second tenth of the samples (after warm-up) to the last."""
    n = len(values)
    tenth = max(1, n // 10)
    start = window_mean(values, tenth, 2 * tenth)
    end = window_mean(values, n - tenth, n)
    return (end - start) / start if start > 0 else 0.0


def shown(arg):
    """A path inside the repository as a relative one, for the table's command line."""
    try:
        return str(pathlib.Path(arg).resolve().relative_to(ROOT)) if os.sep in arg else arg
    except ValueError:
        return arg


def plot(path, ticks, series, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 3.2))
    for label, values in series:
        ax.plot(ticks, values, label=label)
    ax.set_xlabel("tick")
    ax.set_ylabel("MiB")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(loc="center right", fontsize=8)
    ax.set_title(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ticks", type=int, default=1_000_000)
    ap.add_argument("--every", type=int, default=0, help="memory sample every N ticks (default ticks/200)")
    ap.add_argument("--record-every", type=int, default=100)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--experiment", default=str(ROOT / "arenas/foraging.argos"))
    ap.add_argument("--essaim", default=str(ROOT / "build/essaim"))
    ap.add_argument("--out", default=str(ROOT / "runs/soak"))
    ap.add_argument("--bench-dir", default=str(ROOT / "bench"))
    ap.add_argument("--set", action="append", default=[], metavar="PATH=VALUE", help="passed to essaim run")
    ap.add_argument("--no-run", action="store_true", help="only tabulate and plot the run already in --out")
    ap.add_argument("--name", default="soak", help="bench files: NAME.md and NAME-memory.png")
    a = ap.parse_args()
    every = a.every or max(1, a.ticks // 200)
    out = pathlib.Path(a.out)
    cmd = [a.essaim, "run", a.experiment, "--ticks", str(a.ticks), "--threads", str(a.threads),
           "--record", f"every={a.record_every}", "--memory-log", str(every), "--quiet", "--out", str(out)]
    for override in a.set:
        cmd += ["--set", override]
    # Interrupted (Ctrl-C, SIGTERM: exit 130/143) still counts: the samples up to then are there.
    rc = 0 if a.no_run else subprocess.call(cmd)
    memory_csv = out / "memory.csv"
    rows = list(csv.DictReader(open(memory_csv))) if memory_csv.exists() else []
    if rc not in (0, 130, 143) or len(rows) < 2:
        sys.exit(f"soak: essaim exited {rc} with {len(rows)} memory samples ({' '.join(cmd)})")
    summary = json.loads((out / "summary.json").read_text())
    wall = summary["wall_seconds"]

    mib = 2.0 ** 20
    ticks = [int(r["tick"]) for r in rows]
    rss = [int(r["rss_bytes"]) / mib for r in rows]
    lua = [int(r["lua_bytes"]) / mib for r in rows]
    loop = [int(r["loop_lua_bytes"]) / mib for r in rows]
    table = [("resident set", rss), ("controllers' Lua states", lua), ("loop functions' Lua state", loop)]
    flat = all(growth(v) < MAX_GROWTH for _, v in table)
    recording = (out / "recording.bin").stat().st_size / mib

    bench = pathlib.Path(a.bench_dir)
    bench.mkdir(parents=True, exist_ok=True)
    name = pathlib.Path(a.experiment).name
    plot(bench / f"{a.name}-memory.png", ticks,
         [("resident set", rss), ("controllers' Lua (30 states)", lua), ("loop functions' Lua", loop)],
         f"{name}: {ticks[-1]:,} ticks, --record every={a.record_every}, {a.threads} thread(s)")

    def cells(v):
        return f"{v[0]:.2f} | {max(v):.2f} | {v[-1]:.2f}"

    lines = [
        f"# Soak run: {name}, {summary['ticks']:,} ticks",
        "",
        f"`{' '.join(['essaim'] + [shown(c) for c in cmd[1:]])}` (from tools/soak.py)",
        f"on {platform.node() or 'this machine'} ({os.cpu_count()} cores, shared), "
        f"{time.strftime('%Y-%m-%d', time.gmtime())}: {wall:.0f} s wall, "
        f"{summary['ticks'] / wall:.0f} ticks/s, recording.bin {recording:.1f} MiB, "
        f"{summary['robots_alive']} of {summary['robots']} robots alive at the end, status {summary['status']}"
        + (f" (stopped at tick {summary['ticks']:,} of {a.ticks:,})." if summary["ticks"] < a.ticks else "."),
        f"Memory sampled every {every} ticks ({len(rows)} samples), shown in {a.name}-memory.png.",
        "",
        "| memory (MiB) | first sample | max | last | growth after warm-up |",
        "|---|---|---|---|---|",
    ] + [f"| {label} | {cells(v)} | {growth(v) * 100:+.1f} % |" for label, v in table] + [
        "",
        "Growth after warm-up: mean of the last tenth of the samples against the mean of the second "
        f"tenth. Verdict: {'flat' if flat else 'NOT flat'} (limit {MAX_GROWTH * 100:.0f} %).",
    ]
    (bench / f"{a.name}.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    sys.exit(0 if flat else 1)


if __name__ == "__main__":
    main()
