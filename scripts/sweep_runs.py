"""Running the runs of scripts/sweep.py: one essaim process per run, here (`-j N`) or on a
Dask cluster (`--scheduler`), and the run folder each one leaves (essaim's outputs, its
stdout/stderr and the sweep's record of its command line).

Dask workers need not have this file: run_dask ships this module's functions (run_remote and
what it calls) by value, so run_remote and its helpers must stay in this module."""
from __future__ import annotations

import concurrent.futures as cf
import ctypes
import json
import os
import pickle
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import uuid
from pathlib import Path
from typing import TYPE_CHECKING

from sweep_identity import RUN_RECORD, record_argv

if TYPE_CHECKING:
    from sweep_spec import Run, Sweep


# Linux's prctl(PR_SET_PDEATHSIG): the kernel signals a child when its parent dies.
PR_SET_PDEATHSIG = 1


def die_with_parent():
    """A preexec_fn: the essaim child gets SIGTERM (and writes its `interrupted` summary)
    when the sweep process dies, even by SIGKILL; if the sweep is already gone, exit."""
    parent = os.getpid()
    # Opened here, before the fork (and not at import: Dask ships run_remote by value).
    libc = ctypes.CDLL(None, use_errno=True) if sys.platform.startswith("linux") else None

    def setup():
        if libc is not None:
            libc.prctl(PR_SET_PDEATHSIG, signal.SIGTERM)
        if os.getppid() != parent:
            os._exit(1)
    return setup


# ----------------------------------------------------------------------------------------
# One run: on a worker, and its folder


def run_remote(argv: list[str], workdir: str, timeout: float | None) -> dict:
    """Run one essaim process in a temporary folder; return its exit status and output files.

    Used on Dask workers (no shared filesystem needed: the files travel back in the result).
    `argv` ends with `--out <placeholder>`, replaced here by the temporary folder.
    """
    tmp = tempfile.mkdtemp(prefix="essaim-run-")
    try:
        argv = argv[:-1] + [tmp]
        start = time.time()
        try:
            p = subprocess.run(argv, cwd=workdir, capture_output=True, text=True,
                               errors="replace", timeout=timeout, preexec_fn=die_with_parent())
            rc, stdout, stderr = p.returncode, p.stdout, p.stderr
        except FileNotFoundError as e:
            rc, stdout, stderr = 127, "", f"cannot start {argv[0]} in {workdir}: {e.strerror}"
        except subprocess.TimeoutExpired as e:
            rc, stdout = -9, ""
            stderr = _text(e.stderr) + f"\ntimed out after {timeout:g} s"
        files = {}
        for name in sorted(os.listdir(tmp)):
            fp = os.path.join(tmp, name)
            if os.path.isfile(fp) and not os.path.islink(fp) and not name.startswith("."):
                with open(fp, "rb") as f:
                    files[name] = f.read()
        files.update(run_files(tmp))
        return {"returncode": rc, "stdout": stdout, "stderr": stderr, "files": files,
                "host": socket.gethostname(), "elapsed": time.time() - start}
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


def run_files(run_dir: str) -> dict[str, bytes]:
    """The files the run's scripts wrote, below its files/ (summary.json's "files"), by
    their path in the run folder."""
    files = {}
    top = os.path.join(run_dir, "files")
    for root, _, names in os.walk(top):
        for name in sorted(names):
            fp = os.path.join(root, name)
            if os.path.isfile(fp) and not os.path.islink(fp):
                with open(fp, "rb") as f:
                    files[os.path.relpath(fp, run_dir)] = f.read()
    return files


def _text(b) -> str:
    if b is None:
        return ""
    return b.decode(errors="replace") if isinstance(b, bytes) else b


def write_run_folder(run_dir: Path, result: dict, argv: list[str]) -> None:
    """Write a run returned by a remote worker; summary.json last and atomically."""
    if run_dir.exists():
        shutil.rmtree(run_dir)
    run_dir.mkdir(parents=True)
    files = dict(result["files"])
    summary = files.pop("summary.json", None)
    for name, data in files.items():
        (run_dir / name).parent.mkdir(parents=True, exist_ok=True)  # files/... of the run's own
        (run_dir / name).write_bytes(data)
    write_logs(run_dir, result)
    write_record(run_dir, argv, result)
    if summary is not None:
        tmp = run_dir / ".summary.json.tmp"
        tmp.write_bytes(summary)
        os.replace(tmp, run_dir / "summary.json")


def write_logs(run_dir: Path, result: dict) -> None:
    for name in ("stdout", "stderr"):
        if result.get(name):
            (run_dir / f"{name}.txt").write_text(result[name], encoding="utf-8")


def write_record(run_dir: Path, argv: list[str], result: dict) -> None:
    rec = {"argv": record_argv(argv), "host": result.get("host"),
           "elapsed": result.get("elapsed"), "returncode": result["returncode"]}
    (run_dir / RUN_RECORD).write_text(json.dumps(rec, indent=1) + "\n", encoding="utf-8")


# ----------------------------------------------------------------------------------------
# Executors


class Interrupted(Exception):
    pass


def run_local(sweep: Sweep, todo: list[Run], essaim: str, jobs: int, on_done) -> None:
    """Run essaim processes, `jobs` at a time; on Ctrl-C kill them and raise Interrupted."""
    lock = threading.Lock()
    procs: set[subprocess.Popen] = set()
    stop = threading.Event()

    def one(run: Run):
        run_dir = sweep.out / "runs" / run.key
        argv = sweep.argv(run, essaim, str(run_dir))
        with lock:
            if stop.is_set():
                return None
            if run_dir.exists():
                shutil.rmtree(run_dir)  # leftovers of an interrupted or failed run
            run_dir.mkdir(parents=True)
            start = time.time()
            try:
                # Own session: Ctrl-C reaches only the sweep, which kills its children itself.
                p = subprocess.Popen(argv, cwd=sweep.workdir, stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE, text=True, errors="replace",
                                     start_new_session=True, preexec_fn=die_with_parent())
            except OSError as e:
                return run, {"returncode": 127, "stdout": "", "files": {},
                             "stderr": f"cannot start {essaim}: {e.strerror}"}
            procs.add(p)
        try:
            stdout, stderr = p.communicate(timeout=sweep.timeout)
        except subprocess.TimeoutExpired:
            p.kill()
            stdout, stderr = p.communicate()
            stderr += f"\ntimed out after {sweep.timeout:g} s"
        finally:
            with lock:
                procs.discard(p)
        if stop.is_set():
            return None  # killed by us: not a result
        return run, {"returncode": p.returncode, "stdout": stdout, "stderr": stderr,
                     "host": socket.gethostname(), "elapsed": time.time() - start,
                     "argv": argv}

    ex = cf.ThreadPoolExecutor(max_workers=jobs)
    futures = []
    try:
        futures = [ex.submit(one, r) for r in todo]
        for fut in cf.as_completed(futures):
            res = fut.result()
            if res is not None:
                run, result = res
                run_dir = sweep.out / "runs" / run.key
                write_logs(run_dir, result)
                if "argv" in result:
                    write_record(run_dir, result["argv"], result)
                on_done(run, result)
    except KeyboardInterrupt:
        stop.set()
        for f in futures:
            f.cancel()
        with lock:
            for p in procs:
                _kill(p)
        ex.shutdown(wait=True, cancel_futures=True)
        raise Interrupted() from None
    ex.shutdown(wait=True)


def _kill(p: subprocess.Popen) -> None:
    try:
        os.killpg(p.pid, signal.SIGTERM)
    except (ProcessLookupError, PermissionError):
        pass
    try:
        p.wait(timeout=2)
    except subprocess.TimeoutExpired:
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass


class ByValue:
    """A function of this module as Dask ships it: by value (cloudpickle), so that the
    scheduler and the workers unpickle the task without importing this module, which they
    do not have (scripts/ is not on their path). Pickled, it is the call
    pickle.loads(<the function, cloudpickled>), which gives the function back.

    Registering the module with cloudpickle is not enough: Dask tries the plain pickle
    first, which names a function of an importable module, and turns to cloudpickle only for
    functions of __main__ (as run_remote was while it lived in sweep.py, run as a script)."""

    def __init__(self, fn):
        import cloudpickle
        cloudpickle.register_pickle_by_value(sys.modules[fn.__module__])
        self.fn, self.data = fn, cloudpickle.dumps(fn)

    def __call__(self, *args, **kwargs):
        return self.fn(*args, **kwargs)

    def __reduce__(self):
        return pickle.loads, (self.data,)


def run_dask(sweep: Sweep, todo: list[Run], essaim: str, scheduler: str, on_done) -> None:
    """Send the runs to a Dask cluster; workers return the run's files, written here."""
    from dask.distributed import Client, as_completed

    remote = ByValue(run_remote)
    client = Client(scheduler, timeout="30s")
    futures = {}
    try:
        for run in todo:
            argv = sweep.argv(run, essaim, "@OUT@")
            fut = client.submit(remote, argv, str(sweep.workdir), sweep.timeout,
                                key=f"essaim-{run.key}-{uuid.uuid4().hex[:8]}", pure=False,
                                retries=0)
            futures[fut] = (run, argv)
        for fut in as_completed(list(futures)):
            run, argv = futures.pop(fut)
            try:
                result = fut.result()
            except Exception as e:  # the task itself failed: worker lost, unpicklable...
                result = {"returncode": -1, "stdout": "", "files": {},
                          "stderr": f"dask task failed: {type(e).__name__}: {e}"}
            run_dir = sweep.out / "runs" / run.key
            write_run_folder(run_dir, result, argv)
            result["argv"] = argv
            on_done(run, result)
    except KeyboardInterrupt:
        client.cancel(list(futures), force=True)
        raise Interrupted() from None
    finally:
        client.close()
