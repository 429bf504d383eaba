"""A SIERRA pipeline over the foraging experiment with hpc.local (stages 1 to 4: generate,
run, average, graph), and the same pipeline again: its runs take the seeds SIERRA kept
(--preserve-seeds, its default) and give averages identical to the byte."""
from pathlib import Path

from sierra_support import PIPELINE, batch_root, check_batch, seeds, sierra_cli, sierra_env


def averages(root: Path) -> dict[str, bytes]:
    stats = root / "statistics"
    return {str(p.relative_to(stats)): p.read_bytes() for p in sorted(stats.rglob("*"))
            if p.is_file() and "exec" not in p.parts}


def test_local_pipeline_runs_averages_draws_and_repeats(tmp_path):
    env = sierra_env()
    args = [*PIPELINE, "--execenv=hpc.local", "--physics-n-engines=1",
            f"--sierra-root={tmp_path / 'sierra'}", "--pipeline", "1", "2", "3", "4"]
    sierra_cli(args, env, tmp_path)
    root = batch_root(tmp_path / "sierra")
    check_batch(root)
    first_seeds, first = seeds(root), averages(root)
    assert len(set(first_seeds)) == 4, first_seeds  # a seed per run
    assert any(name.endswith("metrics.mean") for name in first)

    sierra_cli([*args[:-5], "--exp-overwrite", "--pipeline", "1", "2", "3"], env, tmp_path)
    assert seeds(root) == first_seeds
    assert averages(root) == first
