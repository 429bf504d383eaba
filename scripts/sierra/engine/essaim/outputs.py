"""A finished essaim run's outputs, laid out for SIERRA's processing stages (stage 3 reads
every CSV under the run's output leaf that a graph names).

`essaim run` already writes `timeseries.csv` (one row per sample) and the loop functions'
own files under `files/`; this adds the scalars SIERRA cannot read from JSON:
  metrics.csv   one row: the numbers of metrics.json and of the objects in it, keys joined
                with '.' (`trips_total`, `trips_per_source.A`); deeper objects, lists and
                strings are left out (their keys change from run to run: `first_touch_by_robot`)
  run.csv       one row: the run's numbers from summary.json (ticks, robots_alive,
                wall_seconds, robot_steps_per_second, ...)
Standard library only: it runs on the cluster node that ran the run, with SIERRA's Python.

SIERRA averages an experiment's runs column by column and wants the same columns, of the
same type, in every run: numbers are written as floats (`82.0`), and a key that some runs
leave out (`first_discovery_tick` when nothing was found) would stop its stage 3, so once an
experiment's runs are done, `--align` keeps in the runs of each experiment under SIERRA's
exp-outputs/ the columns that all of them have (an average over some runs only would
mislead).

    python3 outputs.py RUN_OUTPUT_DIR        # exit 1 when the run did not end `ok`
    python3 outputs.py --align EXP_OUTPUTS   # SIERRA's exp-outputs/ folder
"""
from __future__ import annotations

import csv
import json
import sys
from pathlib import Path


def scalars(value, prefix: str = "", depth: int = 2) -> dict[str, float]:
    """The numbers of a JSON value down to `depth` levels of objects, flattened:
    {'a': {'b': 1}} -> {'a.b': 1}."""
    if isinstance(value, (bool, int, float)):
        return {prefix: float(value)}
    if isinstance(value, dict) and depth > 0:
        out: dict[str, float] = {}
        for key in sorted(value):
            out.update(scalars(value[key], f"{prefix}.{key}" if prefix else str(key), depth - 1))
        return out
    return {}  # lists, strings, null, deeper objects: not a column


def write_row(path: Path, row: dict[str, float]) -> None:
    tmp = path.with_suffix(".csv.tmp")
    with tmp.open("w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(row.keys())
        w.writerow(row.values())
    tmp.replace(path)


def convert(run_dir: Path) -> str:
    """Writes metrics.csv and run.csv beside the JSON files; returns the run's status."""
    summary = json.loads((run_dir / "summary.json").read_text(encoding="utf-8"))
    write_row(run_dir / "run.csv", scalars(summary))
    metrics = run_dir / "metrics.json"
    if metrics.exists():
        row = scalars(json.loads(metrics.read_text(encoding="utf-8")))
        if row:
            write_row(run_dir / "metrics.csv", row)
    return str(summary.get("status", "unknown"))


def align(exp_outputs: Path) -> None:
    """Every experiment's runs' metrics.csv and run.csv with the columns they share."""
    for exp in sorted(p for p in exp_outputs.iterdir() if p.is_dir()):
        groups: dict[Path, list[Path]] = {}
        for run in sorted(p for p in exp.iterdir() if p.is_dir()):
            for f in list(run.rglob("metrics.csv")) + list(run.rglob("run.csv")):
                groups.setdefault(f.relative_to(run), []).append(f)
        for files in groups.values():
            _align_files(files)


def _align_files(files: list[Path]) -> None:
    rows = []
    for f in files:
        with f.open(newline="", encoding="utf-8") as fh:
            rows.append(next(csv.DictReader(fh), {}))
    columns = sorted(set(rows[0]).intersection(*rows[1:]))
    for f, row in zip(files, rows):
        if list(row) != columns:
            write_row(f, {c: row[c] for c in columns})


def main(argv: list[str]) -> int:
    if len(argv) == 3 and argv[1] == "--align":
        align(Path(argv[2]))
        return 0
    if len(argv) != 2:
        print("usage: outputs.py RUN_OUTPUT_DIR | --align EXP_OUTPUTS_DIR", file=sys.stderr)
        return 2
    run_dir = Path(argv[1])
    try:
        status = convert(run_dir)
    except (OSError, ValueError) as e:
        print(f"essaim sierra: {run_dir}: {e}", file=sys.stderr)
        return 1
    if status != "ok":
        print(f"essaim sierra: {run_dir}: run status '{status}' (summary.json)", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
