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
import os
import re
import shutil
import signal
import sys
from pathlib import Path

# The sweep's parts, beside this file (sweep_*.py, file_columns.py): this file is the command.
# What other code imports from sweep.py is re-exported here.
sys.path.insert(0, str(Path(__file__).resolve().parent))
from sweep_spec import (  # noqa: E402,F401
    SWEEP_KEYS, Run, Sweep, SweepError, check_set_path, expand_values, format_value,
    load_file_columns, load_sweep, run_key, short_names, validate_paths)
from sweep_identity import (  # noqa: E402,F401
    RUN_RECORD, InputHashes, command_change, essaim_version, finished, finished_any, fnv1a64,
    option_words, plan_runs, read_json, record_argv, shown_path, stale_causes)
from sweep_runs import (  # noqa: E402,F401
    PR_SET_PDEATHSIG, Interrupted, die_with_parent, run_dask, run_files, run_local, run_remote,
    write_logs, write_record, write_run_folder)
from sweep_table import (  # noqa: E402,F401
    ERROR_LINES, RUN_COLUMNS, SKIPPED_METRICS, SUMMARY_KEYS, failed_row, flatten_metrics,
    flatten_summary, make_table, ok_row, stderr_tail, write_table, write_timeseries)


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
