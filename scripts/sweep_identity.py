"""Run identity for scripts/sweep.py (docs/sweeps.md, "Resuming, Ctrl-C"): is a run folder a
finished run of this command line, is a finished run still the run this sweep would make
(input files, essaim version, settings), and which runs to redo, for which causes."""
from __future__ import annotations

import json
import subprocess
from collections import Counter
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from sweep_spec import Run, Sweep

# Files the sweep itself writes into a run folder (next to essaim's outputs).
RUN_RECORD = "sweep-run.json"


# ----------------------------------------------------------------------------------------
# A run's folder: is it finished?


def read_json(path: Path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def finished(run_dir: Path, argv_record: list[str], strict: bool = False) -> bool:
    """True when the folder holds a valid summary.json of a successful run of this command line.

    essaim writes summary.json last, also for runs that failed or were interrupted (with
    `status` "failed"/"interrupted"): those are not finished. The sweep's own record says
    which command line made the folder and how it exited; a folder without it was not
    finished under the sweep's eye (an orphaned essaim of a killed sweep, or the sweep
    stopped just after essaim exited): it is redone.
    """
    summary = read_json(run_dir / "summary.json")
    if not isinstance(summary, dict):
        return False
    if summary.get("status", "ok") in ("failed", "interrupted"):
        return False
    if strict and summary.get("controller_errors"):
        return False
    record = read_json(run_dir / RUN_RECORD)
    if not isinstance(record, dict):
        return False
    if record.get("argv") != argv_record:
        return False  # made by another version of the sweep file (other ticks, sets...)
    return record.get("returncode") == 0


# ----------------------------------------------------------------------------------------
# Run identity: is a finished run still the run this sweep would make?

FNV_OFFSET, FNV_PRIME, MASK64 = 0xcbf29ce484222325, 0x100000001b3, (1 << 64) - 1


def fnv1a64(data: bytes) -> str:
    """FNV-1a 64 of a file's bytes, written as essaim writes it in summary.json."""
    h = FNV_OFFSET
    for b in data:
        h = ((h ^ b) * FNV_PRIME) & MASK64
    return f"fnv1a64:{h:016x}"


class InputHashes:
    """The current content hash of each input file, computed once per sweep; None when the
    file is missing or unreadable."""

    def __init__(self):
        self._hashes: dict[str, str | None] = {}

    def __call__(self, path: str) -> str | None:
        if path not in self._hashes:
            try:
                self._hashes[path] = fnv1a64(Path(path).read_bytes())
            except OSError:
                self._hashes[path] = None
        return self._hashes[path]


def shown_path(path: str) -> str:
    """A path as the user knows it: relative to the current folder when under it."""
    try:
        return str(Path(path).resolve().relative_to(Path.cwd()))
    except ValueError:
        return path


def stale_causes(summary: dict, experiment: Path, version: str | None,
                 hashes: InputHashes) -> list[str]:
    """Why a finished run no longer stands for this sweep: each input file of its
    summary.json (arena, controllers, loop functions, required modules, floor images) that
    changed or is gone, and another essaim version. Seed and overrides are in the sweep's
    own record of the command line (checked before). A summary without an input list
    (older essaim) is judged by its experiment file alone."""
    causes = []
    stored = summary.get("essaim_version")
    if version is not None and stored != version:
        causes.append(f"essaim version changed ({stored} -> {version})")
    inputs = summary.get("inputs")
    if not isinstance(inputs, list):
        inputs = [{"path": summary.get("experiment") or str(experiment),
                   "hash": summary.get("experiment_hash")}]
    for item in inputs:
        path = item.get("path") if isinstance(item, dict) else None
        if not isinstance(path, str):
            causes.append("summary.json lists an input without a path")
            continue
        now = hashes(path)
        if now is None:
            causes.append(f"{shown_path(path)} is missing")
        elif now != item.get("hash"):
            causes.append(f"{shown_path(path)} changed")
    return causes


def command_change(run_dir: Path, argv_record: list[str]) -> str | None:
    """'settings changed (...)' when the run's recorded command line is not this sweep's."""
    record = read_json(run_dir / RUN_RECORD)
    old = record.get("argv") if isinstance(record, dict) else None
    if not isinstance(old, list) or old == argv_record:
        return None
    was, now = option_words(old), option_words(argv_record)
    gone, added = [w for w in was if w not in now], [w for w in now if w not in was]
    what = "; ".join(part for part in (f"now {', '.join(added)}" if added else "",
                                       f"was {', '.join(gone)}" if gone else "") if part)
    return f"sweep settings changed ({what or 'argument order'})"


def option_words(argv: list[str]) -> list[str]:
    """A command line as its options with their values: ['--ticks 20', '--set a=1', ...]."""
    words, i = [], 0
    while i < len(argv):
        if argv[i].startswith("--") and i + 1 < len(argv) and not argv[i + 1].startswith("--"):
            words.append(f"{argv[i]} {argv[i + 1]}")
            i += 2
        else:
            words.append(argv[i])
            i += 1
    return words


def plan_runs(sweep: Sweep, runs: list[Run], essaim: str, version):
    """The runs to do, and {cause: number of finished runs redone for it}. `version` is
    essaim's version, or a function giving it (asked only when a finished run is judged)."""
    hashes, causes, todo = InputHashes(), Counter(), []
    for r in runs:
        run_dir = sweep.out / "runs" / r.key
        argv = record_argv(sweep.argv(r, essaim, ""))
        if not finished(run_dir, argv, sweep.strict):
            change = command_change(run_dir, argv) if (run_dir / "summary.json").is_file() else None
            if change and finished_any(run_dir, sweep.strict):
                causes[change] += 1
            todo.append(r)
            continue
        if callable(version):
            version = version()
        why = stale_causes(read_json(run_dir / "summary.json"), sweep.experiment, version, hashes)
        causes.update(why)
        if why:
            todo.append(r)
    return todo, causes


def finished_any(run_dir: Path, strict: bool) -> bool:
    """A run that succeeded, whatever command line made it."""
    record = read_json(run_dir / RUN_RECORD)
    argv = record.get("argv") if isinstance(record, dict) else None
    return isinstance(argv, list) and finished(run_dir, argv, strict)


def essaim_version(essaim: str) -> str | None:
    """`essaim --version`'s number; None when it cannot be asked (then not compared)."""
    try:
        r = subprocess.run([essaim, "--version"], capture_output=True, text=True, timeout=10)
    except (OSError, subprocess.TimeoutExpired):
        return None
    words = r.stdout.split()
    return words[-1] if r.returncode == 0 and words else None


def record_argv(argv: list[str]) -> list[str]:
    """The part of a run's command line that defines its results (no binary, no --out)."""
    return argv[1:-2]
