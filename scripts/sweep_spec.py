"""The sweep file of scripts/sweep.py (docs/sweeps.md, "A sweep file"): the runs it makes
(Run, Sweep), loading and checking it, expanding parameter values, the run keys that name
the run folders, and checking its --set paths with `essaim check` before any run."""
from __future__ import annotations

import hashlib
import itertools
import math
import os
import re
import subprocess
import tomllib
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

import file_columns

SWEEP_KEYS = {"experiment", "params", "ticks", "seeds", "set", "out", "essaim", "workdir",
              "strict", "args", "timeout", "file_columns"}


class SweepError(Exception):
    """A bad sweep file or command line (exit 2)."""


# ----------------------------------------------------------------------------------------
# Sweep file


@dataclass
class Run:
    key: str                       # folder name under <out>/runs
    params: dict[str, object]      # --set path -> value, in sweep-file order
    seed: int

    def set_args(self) -> list[str]:
        return [f"{p}={format_value(v)}" for p, v in self.params.items()]


@dataclass
class Sweep:
    path: Path                     # the sweep file
    experiment: Path               # absolute
    params: dict[str, list]        # --set path -> values
    seeds: list[int]
    out: Path                      # absolute
    workdir: Path                  # absolute; essaim runs there (controller scripts resolve there)
    ticks: int | None = None
    fixed: dict[str, object] = field(default_factory=dict)
    essaim: str | None = None      # from the sweep file, resolved
    strict: bool = False
    extra_args: list[str] = field(default_factory=list)
    timeout: float | None = None
    # table column -> files/PATH[COLUMN].STAT: a number from a file each run wrote
    file_columns: dict[str, str] = field(default_factory=dict)

    def runs(self) -> list[Run]:
        names = short_names(list(self.params))
        runs = []
        for values in itertools.product(*self.params.values()):
            point = dict(zip(self.params, values))
            for seed in self.seeds:
                runs.append(Run(run_key(point, seed, names), point, seed))
        keys = Counter(r.key for r in runs)
        dup = [k for k, n in keys.items() if n > 1]
        if dup:
            raise SweepError(f"two runs would share the folder {dup[0]!r}: repeated values?")
        return runs

    def argv(self, run: Run, essaim: str, out: str) -> list[str]:
        """The essaim command line of one run."""
        argv = [essaim, "run", str(self.experiment), "--quiet", "--seed", str(run.seed)]
        if self.ticks is not None:
            argv += ["--ticks", str(self.ticks)]
        for p, v in self.fixed.items():
            argv += ["--set", f"{p}={format_value(v)}"]
        for s in run.set_args():
            argv += ["--set", s]
        if self.strict:
            argv.append("--strict")
        argv += self.extra_args
        argv += ["--out", out]
        return argv

    def manifest(self) -> dict:
        return {"sweep_file": str(self.path), "experiment": str(self.experiment),
                "params": self.params, "seeds": self.seeds, "ticks": self.ticks,
                "set": self.fixed, "strict": self.strict, "args": self.extra_args,
                "workdir": str(self.workdir)}


def format_value(v) -> str:
    """A TOML value as the text of an XML attribute."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return repr(v)  # shortest text that reads back the same: 0.1, 10.0, 1e-05
    return str(v)


def expand_values(path: str, spec) -> list:
    """A parameter's values: a list, a scalar, or a range {start, stop, step} (stop included)."""
    if isinstance(spec, list):
        if not spec:
            raise SweepError(f"params.{path}: empty list")
        for v in spec:
            if isinstance(v, (dict, list)):
                raise SweepError(f"params.{path}: values must be numbers, strings or booleans")
        return list(spec)
    if isinstance(spec, dict):
        unknown = set(spec) - {"start", "stop", "step"}
        if unknown or not {"start", "stop"} <= set(spec):
            raise SweepError(f"params.{path}: a range is {{start, stop, step}}, got {sorted(spec)}")
        start, stop, step = spec["start"], spec["stop"], spec.get("step", 1)
        for name, v in (("start", start), ("stop", stop), ("step", step)):
            if isinstance(v, bool) or not isinstance(v, (int, float)):
                raise SweepError(f"params.{path}: range {name} must be a number")
        if step == 0 or (stop - start) * step < 0:
            raise SweepError(f"params.{path}: step {step} never goes from {start} to {stop}")
        n = int(math.floor((stop - start) / step + 1e-9)) + 1
        if n > 100000:
            raise SweepError(f"params.{path}: range has {n} values")
        if all(isinstance(v, int) for v in (start, stop, step)):
            return [start + i * step for i in range(n)]
        # Round away binary noise: 0.1 + 2 * 0.1 is 0.30000000000000004.
        return [round(start + i * step, 12) for i in range(n)]
    if isinstance(spec, (int, float, str, bool)):
        return [spec]
    raise SweepError(f"params.{path}: expected a list, a value or {{start, stop, step}}")


def load_sweep(path: str | Path, out: str | None = None, essaim: str | None = None) -> Sweep:
    """Read and check a sweep file. `out` (from the command line) is relative to the cwd."""
    path = Path(path).resolve()
    try:
        with open(path, "rb") as f:
            doc = tomllib.load(f)
    except OSError as e:
        raise SweepError(f"{path}: {e.strerror}") from None
    except tomllib.TOMLDecodeError as e:
        raise SweepError(f"{path}: {e}") from None
    unknown = set(doc) - SWEEP_KEYS
    if unknown:
        raise SweepError(f"{path}: unknown key(s) {', '.join(sorted(unknown))} "
                         f"(known: {', '.join(sorted(SWEEP_KEYS))})")
    here = path.parent

    if "experiment" not in doc or not isinstance(doc["experiment"], str):
        raise SweepError(f"{path}: `experiment` (path of the .argos file) is required")
    experiment = (here / doc["experiment"]).resolve()
    if not experiment.is_file():
        raise SweepError(f"{path}: experiment {experiment} does not exist")

    raw_params = doc.get("params", {})
    if not isinstance(raw_params, dict):
        raise SweepError(f"{path}: `params` must be a table of PATH = values")
    params = {}
    for p, spec in raw_params.items():
        check_set_path(path, p)
        params[p] = expand_values(p, spec)

    seeds = doc.get("seeds", 1)
    if isinstance(seeds, int) and not isinstance(seeds, bool):
        if seeds < 1:
            raise SweepError(f"{path}: seeds must be >= 1")
        seeds = list(range(1, seeds + 1))
    elif isinstance(seeds, list) and seeds and all(
            isinstance(s, int) and not isinstance(s, bool) and s >= 0 for s in seeds):
        if len(set(seeds)) != len(seeds):
            raise SweepError(f"{path}: repeated seeds")
    else:
        raise SweepError(f"{path}: `seeds` is a count N (seeds 1..N) or a list of seeds")

    ticks = doc.get("ticks")
    if ticks is not None and (isinstance(ticks, bool) or not isinstance(ticks, int) or ticks < 1):
        raise SweepError(f"{path}: `ticks` must be a positive integer")

    fixed = doc.get("set", {})
    if not isinstance(fixed, dict):
        raise SweepError(f"{path}: `set` must be a table of PATH = value")
    for p, v in fixed.items():
        check_set_path(path, p)
        if isinstance(v, (dict, list)):
            raise SweepError(f"{path}: set.{p} must be a single value")
        if p in params:
            raise SweepError(f"{path}: {p} is both in `set` and in `params`")

    if out is not None:
        out_dir = Path(out).resolve()
    elif "out" in doc:
        out_dir = (here / doc["out"]).resolve()
    else:
        out_dir = (Path("sweeps") / path.stem).resolve()

    workdir = (here / doc["workdir"]).resolve() if "workdir" in doc else Path.cwd()
    if not workdir.is_dir():
        raise SweepError(f"{path}: workdir {workdir} is not a folder")

    file_essaim = doc.get("essaim")
    if file_essaim is not None:
        file_essaim = os.path.abspath(here / file_essaim) if "/" in file_essaim else file_essaim

    args = doc.get("args", [])
    if not isinstance(args, list) or not all(isinstance(a, str) for a in args):
        raise SweepError(f"{path}: `args` must be a list of strings")
    timeout = doc.get("timeout")
    if timeout is not None and (not isinstance(timeout, (int, float)) or timeout <= 0):
        raise SweepError(f"{path}: `timeout` must be a positive number of seconds")

    return Sweep(path=path, experiment=experiment, params=params, seeds=seeds, out=out_dir,
                 workdir=workdir, ticks=ticks, fixed=dict(fixed), essaim=file_essaim,
                 strict=bool(doc.get("strict", False)), extra_args=args, timeout=timeout,
                 file_columns=load_file_columns(path, doc.get("file_columns", {})))


def load_file_columns(path: Path, table) -> dict[str, str]:
    """`file_columns`: NAME = "files/PATH[COLUMN].STAT", each checked now."""
    if not isinstance(table, dict):
        raise SweepError(f"{path}: `file_columns` must be a table of NAME = \"files/PATH[COLUMN].STAT\"")
    for name, spec in table.items():
        try:
            file_columns.parse(spec if isinstance(spec, str) else repr(spec))
        except ValueError as e:
            raise SweepError(f"{path}: file_columns.{name}: {e}") from None
    return dict(table)


def validate_paths(sweep: Sweep, essaim: str, timeout: float = 300) -> None:
    """Refuse, before any run, a sweep whose --set paths essaim does not read: a typo such as
    `entity.quantiy` would give rows whose parameter column varies while every run is the
    same. One `essaim check` with the first value of each parameter reports every unknown
    path at once (with "did you mean"). Raises SweepError with essaim's messages about paths."""
    argv = [essaim, "check", str(sweep.experiment), "--quiet"]
    for p, v in sweep.fixed.items():
        argv += ["--set", f"{p}={format_value(v)}"]
    for p, values in sweep.params.items():
        argv += ["--set", f"{p}={format_value(values[0])}"]
    if sweep.strict:
        argv.append("--strict")
    try:
        r = subprocess.run(argv, cwd=sweep.workdir, capture_output=True, text=True,
                           errors="replace", timeout=timeout)
    except (OSError, subprocess.TimeoutExpired) as e:
        raise SweepError(f"cannot check the experiment with {essaim}: {e}") from None
    # Only the paths are judged here: a value that fails (quantity = 5000 that cannot be
    # placed) fails its own runs, as before.
    bad = [line for line in r.stderr.splitlines() if "--set " in line]
    if r.returncode != 0 and bad:
        raise SweepError(f"{sweep.path}: essaim reads nothing at these paths (nothing was run):\n"
                         + "\n".join(bad[:20]))


def check_set_path(sweep_path, p: str) -> None:
    if not re.fullmatch(r"[A-Za-z_][\w\-]*(\[\d+\])?(\.[A-Za-z_][\w\-]*(\[\d+\])?)+", p):
        raise SweepError(f"{sweep_path}: {p!r} is not a --set path (tag.tag.attribute)")


# ----------------------------------------------------------------------------------------
# Run keys


def short_names(paths: list[str]) -> dict[str, str]:
    """The shortest dotted suffix of each --set path that tells it from the others."""
    segs = {p: p.split(".") for p in paths}
    names = {}
    for p in paths:
        for n in range(1, len(segs[p]) + 1):
            cand = segs[p][-n:]
            if all(segs[q][-n:] != cand for q in paths if q != p):
                names[p] = ".".join(cand)
                break
        else:
            names[p] = p
    return names


def _clean(s: str) -> str:
    return re.sub(r"[^A-Za-z0-9._+\-]", "_", s)


def run_key(point: dict, seed: int, names: dict[str, str]) -> str:
    """A readable, stable folder name: `quantity=30__EPSILONGREED=0.1__seed=2`."""
    parts, exact = [], []
    for p, v in point.items():
        text = format_value(v)
        parts.append(f"{_clean(names[p])}={_clean(text)}")
        exact.append(f"{p}={text}")
    parts.append(f"seed={seed}")
    key = "__".join(parts)
    lossy = any(_clean(format_value(v)) != format_value(v) for v in point.values())
    if lossy or len(key) > 150:
        digest = hashlib.sha1("\n".join(exact + [str(seed)]).encode()).hexdigest()[:8]
        key = key[:140] + "~" + digest
    return key
