#!/usr/bin/env python3
"""Optimise a controller's <params> with Optuna (report §7.2.1: optimise these constants first).

    optimise.py STUDY.toml [--trials N] [--ticks N] [--seeds 1,2] [--eval-seeds 101,102]
                [--jobs N] [--scheduler tcp://host:8786] [--multi] [--out DIR] [--essaim PATH]

Objective: mean trips per robot (metrics.json's trips_per_robot_mean) averaged over the
tuning seeds. With --multi: two objectives, trips per robot up and battery deaths down
(metrics.json's dead_count); the result is a Pareto front. The study lives in
<out>/study.db (SQLite): a rerun resumes it and runs only the trials still missing.
Afterwards the best parameters (best.json: a `set` table usable by sweeps and `args` for
`essaim run`) and the experiment file's own values (the baseline) are run on held-apart
seeds, never seen while tuning: <out>/evaluation.json. See README "Optimising the report's
constants".

Each run goes through the `essaim` Python module when it is importable, else through the
`essaim` executable (same results, bit for bit).

Exit status: 0 done; 1 some runs failed; 2 bad study file or command line; 130 interrupted.
"""
from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import tomllib
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

STUDY_KEYS = {"experiment", "workdir", "out", "ticks", "seeds", "eval_seeds", "set", "params", "essaim"}
STUDY_NAME = "essaim"

# The run-identity check is sweep.py's (same hash, same causes).
sys.path.insert(0, str(Path(__file__).resolve().parent))
from sweep import InputHashes, default_essaim, stale_causes  # noqa: E402


class StudyError(Exception):
    """Bad study file or command line (exit 2)."""


class RunFailed(Exception):
    """An essaim run that did not finish cleanly."""


# ----------------------------------------------------------------------------------------
# Study file


def parse_seeds(v, what: str) -> list[int]:
    if isinstance(v, int) and not isinstance(v, bool):
        return list(range(1, v + 1))
    if isinstance(v, str):
        try:
            v = [int(s) for s in v.split(",") if s.strip()]
        except ValueError:
            raise StudyError(f"{what}: '{v}' must be integers separated by commas") from None
    if not isinstance(v, list) or not v or not all(isinstance(s, int) and s >= 0 for s in v):
        raise StudyError(f"{what}: must be a non-empty list of non-negative integers")
    return v


def load_study(path: Path) -> dict:
    try:
        raw = tomllib.loads(path.read_text())
    except OSError as e:
        raise StudyError(f"{path}: {e.strerror}") from None
    except tomllib.TOMLDecodeError as e:
        raise StudyError(f"{path}: {e}") from None
    unknown = set(raw) - STUDY_KEYS
    if unknown:
        raise StudyError(f"{path}: unknown key(s) {', '.join(sorted(unknown))}")
    base = path.parent
    if "experiment" not in raw:
        raise StudyError(f"{path}: missing `experiment`")
    params = raw.get("params") or {}
    if not params:
        raise StudyError(f"{path}: [params] names no parameter to optimise")
    space = {}
    for name, spec in params.items():
        if not isinstance(spec, dict) or "low" not in spec or "high" not in spec:
            raise StudyError(f"{path}: params.\"{name}\" must be {{ low = ..., high = ... }}")
        low, high = spec["low"], spec["high"]
        if not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in (low, high)) or low >= high:
            raise StudyError(f"{path}: params.\"{name}\": low must be a number below high")
        space[name] = {"low": low, "high": high, "int": isinstance(low, int) and isinstance(high, int),
                       "log": bool(spec.get("log", False))}
    fixed = raw.get("set") or {}
    clash = set(fixed) & set(space)
    if clash:
        raise StudyError(f"{path}: {', '.join(sorted(clash))} both in [set] and [params]")
    return {
        "experiment": (base / raw["experiment"]).resolve(),
        "workdir": (base / raw.get("workdir", ".")).resolve(),
        "out": (base / raw["out"]).resolve() if "out" in raw else None,
        "ticks": raw.get("ticks"),
        "seeds": parse_seeds(raw.get("seeds", [1, 2]), "seeds"),
        "eval_seeds": parse_seeds(raw.get("eval_seeds", [101, 102, 103]), "eval_seeds"),
        "set": fixed,
        "space": space,
        "essaim": raw.get("essaim"),
    }


def format_value(v) -> str:
    if isinstance(v, float):
        return repr(round(v, 12))
    return str(v)


# ----------------------------------------------------------------------------------------
# One run: params + seed -> the metrics the objectives need


def run_once(experiment: str, workdir: str, overrides: dict, seed: int, ticks, essaim_bin) -> dict:
    """Runs one experiment; returns {'trips': mean trips per robot, 'deaths': dead robots,
    'identity': what the run read (essaim version, input files and their hashes)}.

    A plain function of plain values, so Dask can ship it to a worker."""
    over = {k: format_value(v) for k, v in overrides.items()}
    try:
        import essaim  # the module: no process start, no output files
    except ImportError:
        essaim = None
    if essaim is not None and not essaim_bin:
        # No chdir (threads share the cwd): scripts resolve next to the experiment file.
        try:
            with essaim.Simulation(experiment, seed=seed, threads=1, overrides=over) as sim:
                sim.step(ticks) if ticks else sim.run()
                m = sim.finish()
                summary = sim.summary
        except essaim.Error as e:
            raise RunFailed(str(e)) from None
    else:
        exe = essaim_bin or default_essaim() or str(Path(workdir) / "build" / "essaim")
        with tempfile.TemporaryDirectory(prefix="essaim-opt-") as out:
            cmd = [exe, "run", experiment, "--quiet", "--seed", str(seed), "--threads", "1", "--out", out]
            if ticks:
                cmd += ["--ticks", str(ticks)]
            for k, v in over.items():
                cmd += ["--set", f"{k}={v}"]
            p = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True)
            if p.returncode != 0:
                raise RunFailed(f"exit {p.returncode}: {p.stderr.strip()[-500:]}")
            m = json.loads((Path(out) / "metrics.json").read_text())
            summary = json.loads((Path(out) / "summary.json").read_text())
    if "trips_per_robot_mean" not in m or "dead_count" not in m:
        raise RunFailed("metrics.json lacks trips_per_robot_mean/dead_count: not the foraging loop functions?")
    return {"trips": float(m["trips_per_robot_mean"]), "deaths": float(m["dead_count"]),
            "identity": run_identity(summary, experiment)}


def run_identity(summary: dict, experiment: str) -> dict:
    """The part of a run's summary that says what it read: kept with its trial, so that a
    resumed study can tell whether the trial still stands."""
    inputs = summary.get("inputs")
    if not isinstance(inputs, list):  # an essaim that does not list them: the experiment file
        inputs = [{"path": os.path.abspath(summary.get("experiment") or experiment),
                   "hash": summary.get("experiment_hash")}]
    return {"essaim_version": summary.get("essaim_version"),
            "inputs": [{"path": i.get("path"), "hash": i.get("hash")} for i in inputs]}


class Runner:
    """Runs (overrides, seed) pairs locally (threads driving processes or GIL-free module
    runs) or on a Dask cluster."""

    def __init__(self, study: dict, ticks, jobs: int, scheduler: str | None, essaim_bin: str | None):
        self.args = (str(study["experiment"]), str(study["workdir"]))
        self.ticks, self.essaim_bin = ticks, essaim_bin
        self.client = None
        if scheduler:
            from dask.distributed import Client
            self.client = Client(scheduler, timeout="30s")
        self.pool = ThreadPoolExecutor(max_workers=max(1, jobs))

    def run_many(self, overrides: dict, seeds: list[int]) -> list[dict]:
        if self.client is not None:
            futs = [self.client.submit(run_once, *self.args, overrides, s, self.ticks, self.essaim_bin, pure=False)
                    for s in seeds]
            return self.client.gather(futs)
        return [self.pool.submit(run_once, *self.args, overrides, s, self.ticks, self.essaim_bin).result()
                for s in seeds]


# ----------------------------------------------------------------------------------------
# The study


def suggest(trial, space: dict) -> dict:
    out = {}
    for name, s in space.items():
        if s["int"]:
            out[name] = trial.suggest_int(name, s["low"], s["high"], log=s["log"])
        else:
            out[name] = trial.suggest_float(name, s["low"], s["high"], log=s["log"])
    return out


def mean(xs):
    return sum(xs) / len(xs)


def make_objective(study_cfg: dict, runner: Runner, seeds: list[int], multi: bool):
    def objective(trial):
        params = suggest(trial, study_cfg["space"])
        results = runner.run_many({**study_cfg["set"], **params}, seeds)
        trips, deaths = mean([r["trips"] for r in results]), mean([r["deaths"] for r in results])
        trial.set_user_attr("trips_per_robot", trips)
        trial.set_user_attr("deaths", deaths)
        trial.set_user_attr("identity", merged_identity([r["identity"] for r in results]))
        trial.set_user_attr("settings", settings)
        return (trips, deaths) if multi else trips
    settings = trial_settings(study_cfg, runner.ticks, seeds)
    return objective


def trial_settings(study_cfg: dict, ticks, seeds) -> dict:
    """What else defines a trial's result besides its parameters."""
    return {"ticks": ticks, "seeds": list(seeds), "set": dict(study_cfg["set"]),
            "experiment": str(study_cfg["experiment"])}


def merged_identity(identities: list[dict]) -> dict:
    """One identity for a trial's runs (the same files, a module only some seeds loaded)."""
    inputs = {}
    for ident in identities:
        for i in ident["inputs"]:
            inputs.setdefault(i["path"], i)
    return {"essaim_version": identities[0]["essaim_version"], "inputs": list(inputs.values())}


def trial_causes(trial, settings: dict, version: str | None, hashes) -> list[str]:
    """Why a stored trial no longer stands: files it read changed or are gone, another
    essaim, other settings (ticks, seeds, fixed overrides). [] when it stands, and for
    trials stored before optimise.py kept this (they are reported apart)."""
    ident = trial.user_attrs.get("identity")
    if not isinstance(ident, dict):
        return []
    causes = stale_causes(ident, Path(settings["experiment"]), version, hashes)
    stored = trial.user_attrs.get("settings")
    if isinstance(stored, dict):
        changed = [k for k in ("ticks", "seeds", "set", "experiment") if stored.get(k) != settings[k]]
        if changed:
            causes.append(f"study settings changed ({', '.join(changed)})")
    return causes


def refresh_study(out: Path, study, settings: dict, version: str | None, multi: bool, seed: int):
    """Redo the stored trials that no longer stand: the study is started again in a new
    study.db (the old one kept as study-stale-N.db), with the trials that stand copied and
    the others queued to run first with their parameters. Prints one line per cause."""
    import optuna
    from collections import Counter
    hashes, causes, stale, kept, unknown = InputHashes(), Counter(), [], [], 0
    for t in study.trials:
        if t.state != optuna.trial.TrialState.COMPLETE:
            continue
        why = trial_causes(t, settings, version, hashes)
        unknown += "identity" not in t.user_attrs
        causes.update(why)
        (stale if why else kept).append(t)
    if unknown:
        print(f"optimise.py: {unknown} stored trial(s) have no record of the files they read "
              "(made by an older optimise.py): reused as they are")
    if not stale:
        return study
    for cause, n in causes.most_common():
        print(f"optimise.py: {cause}: redoing {n} trial{'s' if n != 1 else ''}")
    n = 1
    while (out / f"study-stale-{n}.db").exists():
        n += 1
    (out / "study.db").rename(out / f"study-stale-{n}.db")
    fresh = open_study(out, multi, seed)
    fresh.add_trials(kept)
    for t in stale:
        fresh.enqueue_trial(t.params)
    return fresh


def open_study(out: Path, multi: bool, seed: int):
    import optuna
    out.mkdir(parents=True, exist_ok=True)
    storage = f"sqlite:///{out / 'study.db'}"
    sampler = optuna.samplers.NSGAIISampler(seed=seed) if multi else optuna.samplers.TPESampler(seed=seed)
    directions = ["maximize", "minimize"] if multi else ["maximize"]
    try:
        study = optuna.create_study(study_name=STUDY_NAME, storage=storage, sampler=sampler,
                                    directions=directions, load_if_exists=True)
    except ValueError as e:  # e.g. resuming a single-objective study with --multi
        raise StudyError(f"{out / 'study.db'}: {e}") from None
    if len(study.directions) != len(directions):
        raise StudyError(f"{out / 'study.db'} holds a {'multi' if len(study.directions) > 1 else 'single'}"
                         f"-objective study: rerun {'with' if len(study.directions) > 1 else 'without'} --multi")
    return study


def best_trials(study, multi: bool):
    import optuna
    done = [t for t in study.trials if t.state == optuna.trial.TrialState.COMPLETE]
    if not done:
        return []
    if not multi:
        return [study.best_trial]
    # Pareto front, most trips first
    return sorted(study.best_trials, key=lambda t: -t.values[0])


def write_best(out: Path, study_cfg: dict, trials, multi: bool, tuning_seeds) -> dict:
    def entry(t):
        setp = {**study_cfg["set"], **t.params}
        return {"trial": t.number, "trips_per_robot": t.user_attrs.get("trips_per_robot"),
                "deaths": t.user_attrs.get("deaths"), "tuning_seeds": tuning_seeds,
                "set": setp, "args": [a for k, v in setp.items() for a in ("--set", f"{k}={format_value(v)}")]}
    best = entry(trials[0])
    if multi:
        best["pareto_front"] = [entry(t) for t in trials]
    tmp = out / "best.json.tmp"
    tmp.write_text(json.dumps(best, indent=2) + "\n")
    tmp.replace(out / "best.json")
    return best


def evaluate(study_cfg: dict, runner: Runner, best: dict, seeds: list[int], out: Path) -> dict:
    """Best parameters and the experiment file's own values, on held-apart seeds."""
    rows = {}
    for name, overrides in (("baseline", dict(study_cfg["set"])), ("best", best["set"])):
        res = runner.run_many(overrides, seeds)
        rows[name] = {"set": overrides, "seeds": seeds,
                      "trips_per_robot": [r["trips"] for r in res], "deaths": [r["deaths"] for r in res],
                      "trips_per_robot_mean": mean([r["trips"] for r in res]),
                      "deaths_mean": mean([r["deaths"] for r in res])}
    (out / "evaluation.json").write_text(json.dumps(rows, indent=2) + "\n")
    return rows


def current_version(essaim_bin: str | None) -> str | None:
    """The version the runs will report: the module's, or the executable's."""
    if not essaim_bin:
        try:
            import essaim
            return essaim.__version__
        except ImportError:
            pass
    exe = essaim_bin or default_essaim()
    if not exe:
        return None
    from sweep import essaim_version
    return essaim_version(exe)


def parse_args(argv):
    ap = argparse.ArgumentParser(prog="optimise.py", description=__doc__.split("\n\n")[0],
                                 epilog="Exit status: 0 done, 1 runs failed, 2 bad input, 130 interrupted.")
    ap.add_argument("study", help="the study file (TOML)")
    ap.add_argument("--trials", type=int, default=100, help="trials in the study, resumed ones included (default 100)")
    ap.add_argument("--ticks", type=int, help="ticks per run (default: the study file's, else the experiment's)")
    ap.add_argument("--seeds", help="tuning seeds, e.g. 1,2 (default: the study file's)")
    ap.add_argument("--eval-seeds", help="held-apart seeds, e.g. 101,102,103 (default: the study file's)")
    ap.add_argument("--jobs", "-j", type=int, default=1, help="runs at a time on this machine (default 1)")
    ap.add_argument("--scheduler", metavar="ADDR", help="run on a Dask cluster, e.g. tcp://host:8786")
    ap.add_argument("--multi", action="store_true", help="two objectives: trips up, battery deaths down")
    ap.add_argument("--out", help="study folder (default: the study file's `out`)")
    ap.add_argument("--essaim", metavar="PATH", help="use this essaim executable instead of the Python module")
    ap.add_argument("--sampler-seed", type=int, default=0, help="Optuna sampler seed (default 0)")
    ap.add_argument("--no-eval", action="store_true", help="skip the held-apart evaluation")
    return ap.parse_args(argv)


def main(argv=None) -> int:
    args = parse_args(argv)
    try:
        cfg = load_study(Path(args.study))
        if args.seeds:
            cfg["seeds"] = parse_seeds(args.seeds, "--seeds")
        if args.eval_seeds:
            cfg["eval_seeds"] = parse_seeds(args.eval_seeds, "--eval-seeds")
        if set(cfg["seeds"]) & set(cfg["eval_seeds"]):
            raise StudyError("tuning and held-apart seeds overlap: "
                             + ",".join(map(str, sorted(set(cfg["seeds"]) & set(cfg["eval_seeds"])))))
        if args.trials < 1 or args.jobs < 1:
            raise StudyError("--trials and --jobs must be positive")
        out = Path(args.out).resolve() if args.out else cfg["out"]
        if out is None:
            raise StudyError("no output folder: give --out or `out` in the study file")
        ticks = args.ticks if args.ticks is not None else cfg["ticks"]
        essaim_bin = os.path.abspath(args.essaim) if args.essaim else cfg["essaim"]
        import optuna
        optuna.logging.set_verbosity(optuna.logging.WARNING)
        study = open_study(out, args.multi, args.sampler_seed)
    except StudyError as e:
        print(f"optimise.py: {e}", file=sys.stderr)
        return 2
    runner = Runner(cfg, ticks, args.jobs, args.scheduler, essaim_bin)
    settings = trial_settings(cfg, ticks, cfg["seeds"])
    study = refresh_study(out, study, settings, current_version(essaim_bin), args.multi,
                          args.sampler_seed)
    done = [t for t in study.trials if t.state == optuna.trial.TrialState.COMPLETE]
    todo = max(0, args.trials - len(done))
    print(f"optimise.py: {len(done)} trial(s) stored in {out / 'study.db'}, running {todo} more "
          f"({len(cfg['seeds'])} seed(s) x {ticks or 'the experiment`s'} ticks each, {args.jobs} at a time)")
    failed = 0

    def on_trial(study, trial):
        nonlocal failed
        if trial.state == optuna.trial.TrialState.FAIL:
            failed += 1
        vals = trial.values
        shown = ", ".join(f"{v:.4g}" for v in vals) if vals else trial.state.name
        print(f"  trial {trial.number}: {shown}", flush=True)

    try:
        if todo:
            # Trials in threads: each waits on its runs (processes, or module runs that release
            # the GIL), so --jobs runs go at once.
            study.optimize(make_objective(cfg, runner, cfg["seeds"], args.multi), n_trials=todo,
                           n_jobs=args.jobs, callbacks=[on_trial], catch=(RunFailed,))
        trials = best_trials(study, args.multi)
        if not trials:
            print("optimise.py: no trial completed", file=sys.stderr)
            return 1
        best = write_best(out, cfg, trials, args.multi, cfg["seeds"])
        print(f"optimise.py: best trial {best['trial']}: {best['trips_per_robot']:.4f} trips/robot, "
              f"{best['deaths']:.1f} deaths on tuning seeds; {out / 'best.json'}")
        if not args.no_eval:
            ev = evaluate(cfg, runner, best, cfg["eval_seeds"], out)
            for name, row in ev.items():
                print(f"  held-apart seeds {row['seeds']}: {name:8s} {row['trips_per_robot_mean']:.4f} trips/robot, "
                      f"{row['deaths_mean']:.2f} deaths")
    except KeyboardInterrupt:
        print("optimise.py: interrupted; a rerun resumes the study", file=sys.stderr)
        return 130
    except RunFailed as e:
        print(f"optimise.py: {e}", file=sys.stderr)
        return 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
