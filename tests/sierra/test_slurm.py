"""The local test's pipeline through hpc.slurm on a single-node SLURM cluster the test
starts itself (slurm_cluster.py): `sbatch --wait` submits a job that runs SIERRA
inside its allocation, as SIERRA's hpc.slurm expects; GNU parallel reaches the job's node
through scripts/sierra/srun-ssh, so each essaim run is a step of the job (srun); the job
ends, and its runs, averages and graphs are back in the test's folder."""
import subprocess

from sierra_support import PIPELINE, PLUGINS, batch_root, check_batch, sierra_env
from slurm_cluster import Cluster


def test_slurm_pipeline_runs_through_sbatch_and_comes_back(tmp_path):
    env = sierra_env()
    cluster = Cluster(tmp_path / "slurm")
    cluster.start()
    try:
        job = tmp_path / "job.sh"
        args = " ".join(f"'{a}'" for a in PIPELINE)
        job.write_text("#!/bin/bash\nset -e\n"
                       f"export PARALLEL_SSH={PLUGINS / 'srun-ssh'}\n"
                       f"sierra {args} --execenv=hpc.slurm "
                       f"--sierra-root={tmp_path / 'sierra'} --pipeline 1 2 3 4\n")
        r = subprocess.run(["sbatch", "--wait", "--nodes=1", "--ntasks-per-node=2",
                            "--cpus-per-task=1", f"--output={tmp_path / 'job.out'}", str(job)],
                           cwd=tmp_path, env={**env, **{"SLURM_CONF": str(cluster.conf)}},
                           capture_output=True, text=True, timeout=400)
        log = (tmp_path / "job.out").read_text() if (tmp_path / "job.out").exists() else ""
        assert r.returncode == 0, f"sbatch: {r.stdout}{r.stderr}\n--- job\n{log[-5000:]}"
        assert "Submitted batch job" in r.stdout
    finally:
        cluster.stop()
    root = batch_root(tmp_path / "sierra")
    check_batch(root)
    # SIERRA took 2 runs at a time and 1 thread per run from the job's allocation.
    cmds = (root / "exp-inputs" / "c1-exp0" / "commands.txt").read_text()
    assert "--threads 1" in cmds
