#!/usr/bin/env python3
"""Run a parameter sweep of essaim experiments, locally or on a Dask cluster.

    sweep.py SWEEP.toml [-j N] [--scheduler tcp://host:8786] [--essaim PATH] [--out DIR]

Every (point, seed) of the sweep is one `essaim run ... --quiet --out <out>/runs/<run-key>`
process. The runs' summary.json and metrics.json are gathered into one table, one row per
run, written as <out>/results.parquet and <out>/results.csv; their timeseries.csv into
<out>/timeseries.parquet. A rerun reuses the finished runs that still stand (same files
read, same essaim, same settings) and redoes the others, saying why. See docs/sweeps.md.

Exit status: 0 every run succeeded; 1 some runs failed (they are rows with status "failed");
2 bad sweep file or command line, or essaim not found; 130 interrupted (finished runs kept,
a rerun resumes).
"""
from __future__ import annotations

import argparse
import json
import math
import os
import re
import shutil
import signal
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))  # file_columns.py, beside this file
import file_columns  # noqa: E402
from sweep_spec import (  # noqa: E402,F401
    SWEEP_KEYS, Run, Sweep, SweepError, check_set_path, expand_values, format_value,
    load_file_columns, load_sweep, run_key, short_names, validate_paths)
from sweep_identity import (  # noqa: E402,F401
    RUN_RECORD, InputHashes, command_change, essaim_version, finished, finished_any, fnv1a64,
    option_words, plan_runs, read_json, record_argv, shown_path, stale_causes)
from sweep_runs import (  # noqa: E402,F401
    PR_SET_PDEATHSIG, Interrupted, die_with_parent, run_dask, run_files, run_local, run_remote,
    write_logs, write_record, write_run_folder)

# Summary keys kept as unprefixed columns; every other summary key becomes "summary.<key>".
SUMMARY_KEYS = ("seed", "ticks", "robots", "wall_seconds", "robot_steps_per_second")
# Metrics dicts too wide for a table (one column per robot): skipped, their mean is kept.
SKIPPED_METRICS = ("trips_per_robot",)
# Bookkeeping columns, first in the table.
RUN_COLUMNS = ("run", "status", "returncode", "error", "seed")
ERROR_LINES = 5  # stderr lines kept in the `error` column


# ----------------------------------------------------------------------------------------
# One run: executing it, reading its folder


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


# ----------------------------------------------------------------------------------------
# Command line


# This checkout's own build (scripts/setup.sh makes it): used when `essaim` is not on PATH.
PROJECT_ESSAIM = Path(__file__).resolve().parent.parent / "build" / "essaim"


def default_essaim() -> str | None:
    """`essaim` on PATH, else this checkout's build/essaim; None when neither is there."""
    if shutil.which("essaim"):
        return shutil.which("essaim")
    return str(PROJECT_ESSAIM) if os.access(PROJECT_ESSAIM, os.X_OK) else None


def resolve_essaim(cli: str | None, sweep: Sweep, remote: bool) -> str:
    """--essaim, else $ESSAIM, else the sweep file's `essaim`, else `essaim` on PATH, else
    this checkout's build/essaim."""
    cand = cli or os.environ.get("ESSAIM") or sweep.essaim or "essaim"
    if "/" in cand:
        cand = os.path.abspath(cand)
        if not remote and not os.access(cand, os.X_OK):
            raise SweepError(f"essaim binary {cand} is not an executable file")
        return cand
    if remote:
        return cand  # looked up on the workers' PATH
    found = shutil.which(cand) or (default_essaim() if cand == "essaim" else None)
    if not found:
        raise SweepError(f"`{cand}` is not on PATH and {PROJECT_ESSAIM} is not built: run "
                         "bash scripts/setup.sh, or pass --essaim PATH or set $ESSAIM")
    return found


def parse_args(argv):
    ap = argparse.ArgumentParser(
        prog="sweep.py", description="Run a parameter sweep of essaim experiments.",
        epilog="Exit status: 0 all runs ok, 1 some runs failed, 2 bad input, 130 interrupted.")
    ap.add_argument("sweep", help="the sweep file (TOML)")
    ap.add_argument("-j", "--jobs", type=int, default=os.cpu_count() or 1,
                    help="essaim processes at a time (default: all cores, %(default)s)")
    ap.add_argument("--scheduler", metavar="ADDR",
                    help="run on a Dask cluster, e.g. tcp://host:8786 (-j is then ignored)")
    ap.add_argument("--essaim", metavar="PATH",
                    help="the essaim binary (default: $ESSAIM, the sweep file's `essaim`, "
                         "`essaim` on PATH, or this checkout's build/essaim)")
    ap.add_argument("--out", metavar="DIR",
                    help="output folder (default: the sweep file's `out`, relative to it)")
    ap.add_argument("--dry-run", action="store_true",
                    help="print the runs still to do and their command lines; run nothing")
    ap.add_argument("--no-progress", action="store_true", help="no progress bar")
    args = ap.parse_args(argv)
    if args.jobs < 1:
        ap.error("-j must be >= 1")
    return args


def main(argv=None) -> int:
    args = parse_args(argv)
    try:
        sweep = load_sweep(args.sweep, out=args.out)
        runs = sweep.runs()
        essaim = resolve_essaim(args.essaim, sweep, remote=bool(args.scheduler))
        # On a cluster the binary may exist only on the workers: checked where it is found.
        if not args.scheduler or shutil.which(essaim):
            validate_paths(sweep, essaim)
    except SweepError as e:
        print(f"sweep: {e}", file=sys.stderr)
        return 2

    local = not args.scheduler or shutil.which(essaim)
    todo, causes = plan_runs(sweep, runs, essaim, (lambda: essaim_version(essaim)) if local else None)
    for cause, n in causes.most_common():
        print(f"sweep: {cause}: redoing {n} run{'s' if n != 1 else ''}", file=sys.stderr)
    skipped = len(runs) - len(todo)
    n = min(args.jobs, max(1, len(todo)))
    where = args.scheduler or f"{n} local process{'es' if n > 1 else ''}"
    print(f"sweep: {len(runs)} runs ({len(runs) // len(sweep.seeds)} points x "
          f"{len(sweep.seeds)} seeds), {skipped} already done, {len(todo)} to run on {where}; "
          f"output in {sweep.out}", file=sys.stderr)
    if args.dry_run:
        for r in todo:
            print(" ".join(sweep.argv(r, essaim, str(sweep.out / "runs" / r.key))))
        return 0

    sweep.out.mkdir(parents=True, exist_ok=True)
    (sweep.out / "sweep.json").write_text(json.dumps(sweep.manifest(), indent=1) + "\n")

    failures: dict[str, dict] = {}  # run key -> failed row, for runs of this invocation
    done_now: set[str] = set()

    from tqdm import tqdm
    bar = tqdm(total=len(todo), unit="run", disable=args.no_progress or not todo,
               dynamic_ncols=True, file=sys.stderr)

    def on_done(run: Run, result: dict) -> None:
        done_now.add(run.key)
        run_dir = sweep.out / "runs" / run.key
        if result["returncode"] != 0 or not (run_dir / "summary.json").is_file():
            summary = read_json(run_dir / "summary.json")
            err = stderr_tail(result.get("stderr", "")) or (
                summary.get("failure") if isinstance(summary, dict) else None) or (
                exit_text(result["returncode"]) if result["returncode"] != 0
                else "essaim exited 0 without writing summary.json")
            failures[run.key] = failed_row(run, result["returncode"], err, result.get("host"),
                                           run_dir)
            bar.set_postfix(failed=len(failures), refresh=False)
        bar.update(1)

    old_term = signal.signal(signal.SIGTERM, _sigterm)
    interrupted = False
    try:
        if args.scheduler:
            run_dask(sweep, todo, essaim, args.scheduler, on_done)
        else:
            run_local(sweep, todo, essaim, args.jobs, on_done)
    except Interrupted:
        interrupted = True
    except OSError as e:  # e.g. the scheduler cannot be reached
        bar.close()
        print(f"sweep: {e}", file=sys.stderr)
        return 2
    finally:
        signal.signal(signal.SIGTERM, old_term)
        bar.close()

    # Rows in sweep order: failures of this invocation, and runs finished now or before
    # (a run still to do that was interrupted has no row, whatever its folder holds).
    pending = {r.key for r in todo} - done_now
    rows = []
    for r in runs:
        run_dir = sweep.out / "runs" / r.key
        if r.key in failures:
            rows.append(failures[r.key])
        elif r.key not in pending and (run_dir / "summary.json").is_file():
            rows.append(ok_row(r, run_dir, columns=sweep.file_columns))
    if rows:
        write_table(make_table(rows), sweep.out)
        write_timeseries(runs, rows, sweep.out)
    ok = sum(1 for row in rows if row["status"] == "ok")
    print(f"sweep: {ok} runs ok, {len(failures)} failed, {len(runs) - len(rows)} not run; "
          f"table: {sweep.out / 'results.parquet'} ({len(rows)} rows)", file=sys.stderr)
    if failures:
        report_failures(list(failures.values()))
    if interrupted:
        print("sweep: interrupted; run the same command again to resume", file=sys.stderr)
        return 130
    return 1 if failures else 0


def _sigterm(signum, frame):
    """SIGTERM (e.g. from a batch system) stops the sweep like Ctrl-C."""
    raise KeyboardInterrupt()


def report_failures(rows: list[dict]) -> None:
    """How many runs failed and why, grouped by exit status and the last line of their error
    with numbers blanked (robot fb3 and fb7, line 12 and 13 fall together); each group shows
    the message of its first run."""
    groups: dict[tuple, list[dict]] = {}
    for row in rows:
        last = ((row["error"] or "").strip().splitlines()[-1:] or [""])[0]
        groups.setdefault((row["returncode"], re.sub(r"\d+", "#", last)), []).append(row)
    print(f"sweep: {len(rows)} failed runs:", file=sys.stderr)
    for (rc, _), grp in sorted(groups.items(), key=lambda kv: -len(kv[1])):
        last = ((grp[0]["error"] or "").strip().splitlines()[-1:] or [""])[0]
        examples = ", ".join(r["run"] for r in grp[:3]) + (", ..." if len(grp) > 3 else "")
        print(f"  {len(grp):5d} x {exit_text(rc)}: {last}\n          e.g. {examples}",
              file=sys.stderr)


def exit_text(rc: int) -> str:
    """`exit 2`, or `killed by SIGABRT` for a negative return code (death by signal)."""
    if rc is not None and rc < 0:
        try:
            return f"killed by {signal.Signals(-rc).name}"
        except ValueError:
            return f"killed by signal {-rc}"
    return f"exit {rc}"


if __name__ == "__main__":
    sys.exit(main())
