"""hpc.adhoc and hpc.pbs, stages 1 to 3 (generate, run, average), on this machine:
hpc.adhoc from a nodefile naming it (GNU parallel's `:`), with its cores; hpc.pbs in the
environment a PBS job gives its script (PBS_JOBID, PBS_NODEFILE naming this host, NCPUS),
which SIERRA's hpc.pbs runs on that node: no PBS server is started (Debian has none), so
this checks the essaim engine's side, threads and runs per node from the job, not qsub."""
import socket

from sierra_support import PIPELINE, batch_root, check_batch, sierra_cli, sierra_env


def commands(root):
    return (root / "exp-inputs" / "c1-exp0" / "commands.txt").read_text()


def test_adhoc_pipeline_on_a_nodefile(tmp_path):
    nodefile = tmp_path / "nodes"
    nodefile.write_text("2/:\n")  # 2 cores, this machine
    sierra_cli([*PIPELINE, "--execenv=hpc.adhoc", f"--nodefile={nodefile}",
                f"--sierra-root={tmp_path / 'sierra'}", "--pipeline", "1", "2", "3"],
               sierra_env(), tmp_path)
    root = batch_root(tmp_path / "sierra")
    check_batch(root, graphs=False)
    assert "--threads 1" in commands(root)  # 2 cores, 2 runs at a time


def test_pbs_pipeline_in_a_pbs_job_environment(tmp_path):
    nodefile = tmp_path / "PBS_NODEFILE"
    nodefile.write_text(f"{socket.gethostname()}\n")
    env = sierra_env(PBS_JOBID="42.essaim", PBS_NODEFILE=str(nodefile), NCPUS="2")
    sierra_cli([*PIPELINE, "--execenv=hpc.pbs", "--exec-jobs-per-node=1",
                f"--sierra-root={tmp_path / 'sierra'}", "--pipeline", "1", "2", "3"],
               env, tmp_path)
    root = batch_root(tmp_path / "sierra")
    check_batch(root, graphs=False)
    assert "--threads 2" in commands(root)  # 2 cores, 1 run at a time
