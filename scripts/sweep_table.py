"""The results of scripts/sweep.py (docs/sweeps.md, "The table"): one row per run, from its
folder (summary.json, metrics.json, file_columns) or its failure, the results table
(results.parquet, results.csv) and the time series of all runs (timeseries.parquet)."""
from __future__ import annotations

import json
import math
import os
from pathlib import Path
from typing import TYPE_CHECKING

import file_columns
from sweep_identity import RUN_RECORD, read_json
from sweep_spec import format_value

if TYPE_CHECKING:
    from sweep_spec import Run

# Summary keys kept as unprefixed columns; every other summary key becomes "summary.<key>".
SUMMARY_KEYS = ("seed", "ticks", "robots", "wall_seconds", "robot_steps_per_second")
# Metrics dicts too wide for a table (one column per robot): skipped, their mean is kept.
SKIPPED_METRICS = ("trips_per_robot",)
# Bookkeeping columns, first in the table.
RUN_COLUMNS = ("run", "status", "returncode", "error", "seed")
ERROR_LINES = 5  # stderr lines kept in the `error` column


def stderr_tail(text: str, n: int = ERROR_LINES) -> str:
    """The last n lines of stderr that say something: no blank lines, no Lua traceback
    frames (`stack traceback:` and the tab-indented lines under it; stderr.txt has them)."""
    lines, in_traceback = [], False
    for ln in text.splitlines():
        if ln.strip() == "stack traceback:":
            in_traceback = True
            continue
        if in_traceback and ln.startswith(("\t", " ")):
            continue
        in_traceback = False
        if ln.strip():
            lines.append(ln.rstrip())
    return "\n".join(lines[-n:])


# ----------------------------------------------------------------------------------------
# The table


def _scalar(v) -> bool:
    return v is None or isinstance(v, (bool, int, float, str))


def flatten_metrics(metrics: dict) -> dict:
    """metrics.json as columns: scalars as-is, dicts of scalars as `name.key`, lists as JSON."""
    row = {}
    for k, v in metrics.items():
        if k in SKIPPED_METRICS:
            continue
        if isinstance(v, dict) and all(_scalar(x) for x in v.values()):
            for kk, vv in v.items():
                row[f"{k}.{kk}"] = vv
        elif isinstance(v, (dict, list)):
            row[k] = json.dumps(v, sort_keys=False)
        else:
            row[k] = v
    return row


def flatten_summary(summary: dict) -> dict:
    """summary.json as columns: SUMMARY_KEYS unprefixed, the rest as `summary.<key>`."""
    row = {}
    for k, v in summary.items():
        name = k if k in SUMMARY_KEYS else f"summary.{k}"
        if isinstance(v, dict) and all(_scalar(x) for x in v.values()):
            for kk, vv in v.items():
                row[f"{name}.{kk}"] = vv
        elif isinstance(v, (dict, list)):
            row[name] = json.dumps(v)
        else:
            row[name] = v
    errors = summary.get("controller_errors")
    row["controller_error_count"] = len(errors) if isinstance(errors, list) else 0
    return row


def ok_row(run: Run, run_dir: Path, host: str | None = None, columns: dict | None = None) -> dict:
    """The row of a finished run, read from its folder; `columns`: the sweep's file_columns."""
    summary = read_json(run_dir / "summary.json") or {}
    row = {"run": run.key, "status": "ok", "returncode": 0, "error": None, "seed": run.seed}
    row.update(run.params)
    row.update(flatten_summary(summary))
    metrics = read_json(run_dir / "metrics.json")
    if isinstance(metrics, dict):
        for k, v in flatten_metrics(metrics).items():
            row[f"metrics.{k}" if k in row else k] = v
    for name, spec in (columns or {}).items():
        row[name] = file_columns.value(run_dir, spec)
    record = read_json(run_dir / RUN_RECORD)
    row["host"] = host or (record.get("host") if isinstance(record, dict) else None)
    return row


def failed_row(run: Run, returncode: int, error: str, host: str | None = None,
               run_dir: Path | None = None) -> dict:
    """The row of a failed run: the sweep's columns, and its summary's when it wrote one."""
    row = {"run": run.key, "status": "failed", "returncode": returncode, "error": error,
           "seed": run.seed}
    row.update(run.params)
    summary = read_json(run_dir / "summary.json") if run_dir else None
    if isinstance(summary, dict):
        for k, v in flatten_summary(summary).items():
            row.setdefault(k, v)
    row["host"] = host
    return row


def make_table(rows: list[dict]):
    """One DataFrame: bookkeeping columns, then parameters, then summary and metrics.

    Column types come from the values themselves: all integers (missing allowed) -> Int64,
    numbers -> float64, anything with text -> string, so Parquet and CSV agree.
    """
    import pandas as pd

    columns = []
    for r in rows:
        for k in r:
            if k not in columns:
                columns.append(k)
    first = [c for c in RUN_COLUMNS if c in columns]
    columns = first + [c for c in columns if c not in first]

    def missing(v):
        return v is None or (isinstance(v, float) and math.isnan(v))

    data = {}
    for c in columns:
        values = [r.get(c) for r in rows]
        present = [v for v in values if not missing(v)]
        if present and all(isinstance(v, int) and not isinstance(v, bool) for v in present):
            data[c] = pd.array(values, dtype="Int64")
        elif present and all(isinstance(v, bool) for v in present):
            data[c] = pd.array(values, dtype="boolean")
        elif present and all(isinstance(v, (int, float)) and not isinstance(v, bool)
                             for v in present):
            data[c] = pd.array([math.nan if missing(v) else float(v) for v in values],
                               dtype="float64")
        else:
            data[c] = pd.array([None if missing(v) else
                                (v if isinstance(v, str) else format_value(v)) for v in values],
                               dtype="string")
    return pd.DataFrame(data, columns=columns)


def write_table(df, out: Path) -> None:
    """results.parquet and results.csv, each written whole (temporary name, then rename)."""
    out.mkdir(parents=True, exist_ok=True)
    for name, write in (("results.parquet", lambda p: df.to_parquet(p, index=False)),
                        ("results.csv", lambda p: df.to_csv(p, index=False))):
        tmp = out / f".{name}.tmp"
        write(tmp)
        os.replace(tmp, out / name)


def write_timeseries(runs: list[Run], rows: list[dict], out: Path) -> bool:
    """<out>/timeseries.parquet: every ok run's timeseries.csv, one table, each row tagged
    with its run, seed and parameters (long format: filter or group by `run`)."""
    import pandas as pd

    ok = {row["run"] for row in rows if row["status"] == "ok"}
    frames = []
    for r in runs:
        csv = out / "runs" / r.key / "timeseries.csv"
        if r.key not in ok or not csv.is_file():
            continue
        try:
            ts = pd.read_csv(csv)
        except (ValueError, OSError):
            continue  # an empty series (no column)
        tags = {"run": r.key, "seed": r.seed, **r.params}
        ts = ts.drop(columns=[c for c in tags if c in ts.columns])
        for i, (k, v) in enumerate(tags.items()):
            ts.insert(i, k, v)
        frames.append(ts)
    if not frames:
        return False
    tmp = out / ".timeseries.parquet.tmp"
    pd.concat(frames, ignore_index=True).to_parquet(tmp, index=False)
    os.replace(tmp, out / "timeseries.parquet")
    return True
