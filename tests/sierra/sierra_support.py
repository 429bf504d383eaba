"""What the SIERRA tests share: where SIERRA is (the venv scripts/setup_sierra.sh makes,
.venv-sierra, or $ESSAIM_SIERRA_VENV), the environment its pipelines run in, and one
pipeline over the foraging experiment, small enough for ctest: 2 swarm sizes x 2 runs x
200 ticks. The tests skip, saying why, where SIERRA is not installed."""
from __future__ import annotations

import csv
import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PLUGINS = ROOT / "scripts" / "sierra"
TEMPLATE = ROOT / "arenas" / "foraging.argos"
PIPELINE = ["--project=projects.foraging", "--engine=engine.essaim",
            f"--expdef-template={TEMPLATE}",
            "--batch-criteria", "population_size.Linear4.C2",  # 2 and 4 robots
            "--n-runs=2", "--exp-setup=exp_setup.T20.K10"]     # 20 s at 10 ticks/s: 200 ticks
SIZES = [2, 4]


def sierra_venv() -> Path:
    venv = Path(os.environ.get("ESSAIM_SIERRA_VENV", ROOT / ".venv-sierra")).absolute()
    if not (venv / "bin" / "sierra").exists():
        pytest.skip(f"SIERRA is not installed in {venv} (scripts/setup_sierra.sh makes it; "
                    "ESSAIM_SIERRA_VENV names another)")
    if shutil.which("parallel") is None:
        pytest.skip("GNU parallel is not installed (apt-get install parallel)")
    return venv


def essaim_binary() -> Path:
    path = os.environ.get("ESSAIM")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("ESSAIM is not set to the essaim executable (ctest sets it)")
    return Path(path).resolve()


def sierra_env(**extra: str) -> dict:
    venv = sierra_venv()
    env = {k: v for k, v in os.environ.items() if not k.startswith(("SLURM_", "PBS_"))}
    env.update(SIERRA_PLUGIN_PATH=str(PLUGINS), ESSAIM=str(essaim_binary()),
               PATH=f"{venv / 'bin'}:{env.get('PATH', '')}", MPLBACKEND="Agg")
    env.pop("PYTHONPATH", None)
    env.update(extra)
    return env


def sierra_cli(args: list[str], env: dict, cwd: Path, timeout: int = 300):
    cli = Path(env["PATH"].split(":")[0]) / "sierra"  # sierra-cli's new name in 1.5.x
    r = subprocess.run([str(cli), *args], cwd=cwd, env=env, capture_output=True, text=True,
                       timeout=timeout)
    assert r.returncode == 0, f"sierra {' '.join(args)}: exit {r.returncode}\n" \
                              f"{r.stdout[-4000:]}\n{r.stderr[-4000:]}"
    return r


def batch_root(sierra_root: Path) -> Path:
    """The batch folder SIERRA made under --sierra-root (one per criterion)."""
    found = [p.parent for p in sierra_root.rglob("exp-inputs")]
    assert len(found) == 1, found
    return found[0]


def read_csv(path: Path) -> list[dict[str, str]]:
    with path.open(newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def check_batch(root: Path, graphs: bool = True) -> None:
    """Every run ran essaim and was laid out for stage 3; stage 3 averaged them; stage 4
    drew the graphs (graphs=True)."""
    for exp, size in zip(("c1-exp0", "c1-exp1"), SIZES):
        for run in (0, 1):
            out = root / "exp-outputs" / exp / f"foraging_run{run}_output" / "essaim"
            assert (out / "summary.json").exists(), out
            metrics = read_csv(out / "metrics.csv")
            assert float(metrics[0]["robots"]) == size and float(metrics[0]["ticks"]) == 200
            assert len(read_csv(out / "timeseries.csv")) == 2  # every 100 ticks
        stats = root / "statistics" / exp
        assert (stats / "metrics.mean").exists() and (stats / "timeseries.mean").exists()
    if graphs:
        inter = root / "graphs" / "inter-exp"
        assert list(inter.glob("*trips-vs-swarm-size.png")), list(inter.iterdir())
        assert list((root / "graphs" / "c1-exp0").glob("*trips-over-time.png"))


def seeds(root: Path) -> list[str]:
    import xml.etree.ElementTree as ET
    return [ET.parse(f).getroot().find(".//experiment").get("random_seed")
            for f in sorted((root / "exp-inputs").rglob("foraging_run*.argos"))]
