"""SIERRA's stage 5 on essaim's outputs: the local pipeline for two controllers of the
foraging project (config/controllers.yaml: ε 0.05 and 0.5), then their comparison, one line
per controller against swarm size."""
from sierra_support import PIPELINE, read_csv, sierra_cli, sierra_env


def test_controllers_compared_in_stage_5(tmp_path):
    env, root = sierra_env(), tmp_path / "sierra"
    for controller in ("greedy", "explorer"):
        sierra_cli([*PIPELINE, "--execenv=hpc.local", "--physics-n-engines=1",
                    f"--controller=foraging.{controller}", f"--sierra-root={root}",
                    "--pipeline", "1", "2", "3", "4"], env, tmp_path)
    sierra_cli(["--project=projects.foraging", "--engine=engine.essaim",
                "--batch-criteria", "population_size.Linear4.C2", f"--sierra-root={root}",
                "--pipeline", "5", "--across", "controllers",
                "--things", "foraging.greedy,foraging.explorer", "--bc-cardinality", "1"],
               env, tmp_path)
    (csv,) = root.rglob("*-cc-csvs/cc-trips-vs-swarm-size*.mean")
    rows = read_csv(csv)
    assert [r["Experiment ID"] for r in rows] == ["c1-exp0", "c1-exp1"]
    assert set(rows[0]) == {"Experiment ID", "foraging.greedy", "foraging.explorer"}
    assert list(root.rglob("*-cc-graphs/*cc-trips-vs-swarm-size*.png"))
