"""A single-node SLURM cluster of Debian's slurm-wlm and munge, started in a folder of the
test's own (its munge key and socket, configuration, state, spool and logs, ports picked
free), as whoever runs the test: root in CI. As another user the daemons run as that user
(SlurmUser, SlurmdUser); where they cannot start so, the test is skipped, saying so
(docs/sierra.md). Clients find it through SLURM_CONF."""
from __future__ import annotations

import getpass
import os
import shutil
import socket
import subprocess
import time
from pathlib import Path

import pytest

DAEMONS = ("munged", "slurmctld", "slurmd", "sbatch", "sinfo", "srun")


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def config(folder: Path, user: str, node: str, cpus: int) -> str:
    lines = {
        "ClusterName": "essaimtest", "SlurmctldHost": f"{node}(127.0.0.1)",
        "SlurmctldPort": free_port(), "SlurmdPort": free_port(),
        "AuthType": "auth/munge", "CredType": "cred/munge",
        "AuthInfo": f"socket={folder / 'munge' / 'socket'}",
        "SlurmUser": user, "SlurmdUser": user,
        "StateSaveLocation": folder / "state", "SlurmdSpoolDir": folder / "spool",
        "SlurmctldPidFile": folder / "slurmctld.pid", "SlurmdPidFile": folder / "slurmd.pid",
        "SlurmctldLogFile": folder / "slurmctld.log", "SlurmdLogFile": folder / "slurmd.log",
        # No cgroups, accounting or MPI: what a daemon can do without the machine's set-up.
        "ProctrackType": "proctrack/linuxproc", "TaskPlugin": "task/none",
        "JobAcctGatherType": "jobacct_gather/none",
        "AccountingStorageType": "accounting_storage/none", "JobCompType": "jobcomp/none",
        "SwitchType": "switch/none", "MpiDefault": "none", "SchedulerType": "sched/builtin",
        "SelectType": "select/cons_tres", "SelectTypeParameters": "CR_CPU",
        "ReturnToService": 2, "SlurmdParameters": "config_overrides",
    }
    text = "".join(f"{k}={v}\n" for k, v in lines.items())
    return text + (f"NodeName={node} NodeAddr=127.0.0.1 CPUs={cpus} State=UNKNOWN\n"
                   "PartitionName=essaim Nodes=ALL Default=YES MaxTime=INFINITE State=UP\n")


class Cluster:
    def __init__(self, folder: Path, cpus: int = 2) -> None:
        missing = [d for d in DAEMONS if shutil.which(d) is None]
        if missing:
            pytest.skip(f"SLURM or munge not installed ({', '.join(missing)}): "
                        "apt-get install slurm-wlm munge")
        self.folder, self.procs = folder, []
        self.user, self.node = getpass.getuser(), socket.gethostname()
        for d in ("munge", "state", "spool"):
            (folder / d).mkdir(mode=0o700, parents=True)
        self.conf = folder / "slurm.conf"
        self.conf.write_text(config(folder, self.user, self.node, cpus))
        self.env = {**os.environ, "SLURM_CONF": str(self.conf)}

    def start(self) -> None:
        self._munge()
        self._daemon(["slurmctld", "-D", "-f", str(self.conf)], "slurmctld.out")
        self._daemon(["slurmd", "-D", "-f", str(self.conf), "-N", self.node], "slurmd.out")
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            r = subprocess.run(["sinfo", "-h", "-o", "%T"], env=self.env, capture_output=True,
                               text=True, timeout=10)
            if r.returncode == 0 and r.stdout.strip() in ("idle", "mixed", "allocated"):
                return
            if any(p.poll() is not None for p in self.procs):
                break
            time.sleep(0.5)
        self._not_started()

    def _munge(self) -> None:
        m = self.folder / "munge"
        key = m / "munge.key"
        key.write_bytes(os.urandom(1024))
        key.chmod(0o600)
        r = subprocess.run(["munged", "--force", f"--socket={m / 'socket'}", f"--key-file={key}",
                            f"--log-file={m / 'log'}", f"--pid-file={m / 'pid'}",
                            f"--seed-file={m / 'seed'}"], capture_output=True, text=True,
                           timeout=30)
        if r.returncode != 0:
            self._not_started(f"munged: {r.stderr}")

    def _daemon(self, argv: list[str], log: str) -> None:
        out = (self.folder / log).open("w")
        self.procs.append(subprocess.Popen(argv, env=self.env, stdout=out,
                                           stderr=subprocess.STDOUT))

    def _not_started(self, why: str = "") -> None:
        logs = "".join(f"\n--- {p.name}\n{p.read_text()[-1500:]}"
                       for p in sorted(self.folder.glob("*.log")) + sorted(self.folder.glob("*.out")))
        self.stop()
        if os.geteuid() != 0:
            pytest.skip(f"a single-node SLURM cluster could not start as user {self.user} "
                        f"(slurmd usually needs root): {why}{logs[-3000:]}")
        pytest.fail(f"the single-node SLURM cluster did not start: {why}{logs}")

    def stop(self) -> None:
        for p in reversed(self.procs):
            if p.poll() is None:
                p.terminate()
                try:
                    p.wait(timeout=20)
                except subprocess.TimeoutExpired:
                    p.kill()
        pid = self.folder / "munge" / "pid"
        if pid.exists():
            try:
                os.kill(int(pid.read_text().split()[0]), 15)
            except (ProcessLookupError, ValueError):
                pass
