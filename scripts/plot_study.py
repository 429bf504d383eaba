#!/usr/bin/env python3
"""Figures of a stored optimise.py study: optimisation history, parameter importances and,
for a multi-objective study, the Pareto front (trips per robot vs battery deaths).

    plot_study.py STUDY_DIR [--out DIR]

Reads STUDY_DIR/study.db; writes history.png, importances.png (and pareto.png) into --out
(default: STUDY_DIR). Exit status: 0 done; 2 no study there or no completed trial.
"""
from __future__ import annotations

import argparse
import sys
import warnings
from pathlib import Path

STUDY_NAME = "essaim"


def short(name: str) -> str:
    return name.rsplit(".", 1)[-1]  # controllers.foraging.params.EPSILONGREED -> EPSILONGREED


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="plot_study.py", description=__doc__.split("\n\n")[0])
    ap.add_argument("study_dir")
    ap.add_argument("--out", help="folder for the figures (default: STUDY_DIR)")
    args = ap.parse_args(argv)
    db = Path(args.study_dir) / "study.db"
    if not db.is_file():
        print(f"plot_study.py: {db}: no study database (run optimise.py first)", file=sys.stderr)
        return 2
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import optuna
    from optuna.visualization import matplotlib as ovm
    optuna.logging.set_verbosity(optuna.logging.WARNING)
    warnings.filterwarnings("ignore", category=optuna.exceptions.ExperimentalWarning)
    study = optuna.load_study(study_name=STUDY_NAME, storage=f"sqlite:///{db}")
    done = [t for t in study.trials if t.state == optuna.trial.TrialState.COMPLETE]
    if not done:
        print(f"plot_study.py: {db}: no completed trial", file=sys.stderr)
        return 2
    out = Path(args.out or args.study_dir)
    out.mkdir(parents=True, exist_ok=True)
    multi = len(study.directions) > 1
    names = ["trips per robot", "battery deaths"] if multi else ["trips per robot"]
    written = []

    def save(ax, name, title):
        fig = (ax[0] if hasattr(ax, "__len__") else ax).figure
        fig.suptitle(title)
        fig.set_size_inches(8, 5)
        fig.tight_layout()
        fig.savefig(out / name, dpi=110)
        plt.close(fig)
        written.append(out / name)

    target = (lambda t: t.values[0]) if multi else None
    save(ovm.plot_optimization_history(study, target=target, target_name=names[0]), "history.png",
         f"Optimisation history ({len(done)} trials)")
    if len(done) >= 2:
        # PED-ANOVA: Optuna's own importance evaluator (fANOVA would need scikit-learn).
        ev = optuna.importance.PedAnovaImportanceEvaluator()
        # With a target PED-ANOVA ranks what makes it low: negate trips (maximised).
        low = (lambda t: -t.values[0]) if multi else None
        ax = ovm.plot_param_importances(study, evaluator=ev, target=low, target_name=names[0])
        ax.set_yticklabels([short(t.get_text()) for t in ax.get_yticklabels()])
        save(ax, "importances.png", f"Parameter importances for {names[0]} (PED-ANOVA)")
    if multi:
        save(ovm.plot_pareto_front(study, target_names=names), "pareto.png", "Pareto front")
    for p in written:
        print(p)
    return 0


if __name__ == "__main__":
    sys.exit(main())
