"""Shared helpers for the sweep and plot tests.

The tests that run simulations need the essaim binary in $ESSAIM (ctest sets it to the
built target); without it they are skipped. Unit tests of the table and the plots run
without it.
"""
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SCRIPTS = ROOT / "scripts"
DATA = Path(__file__).resolve().parent / "data"



def need_python_deps():
    """Skip the calling test module when the Python requirements are not installed."""
    for mod in ("pandas", "pyarrow", "matplotlib", "tqdm"):
        pytest.importorskip(mod, reason=f"{mod} missing: install scripts/requirements.txt "
                                        "into .venv and run the tests with .venv/bin/python")


@pytest.fixture(scope="session")
def essaim(tmp_path_factory):
    """The essaim binary from $ESSAIM, behind a wrapper capping its memory: the tiny test
    experiments need a few MB, and a runaway run must not take the machine's memory."""
    path = os.environ.get("ESSAIM")
    if not path:
        pytest.skip("ESSAIM is not set: point it at the essaim binary (ctest does) "
                    "to run the sweep tests that run simulations")
    if not os.access(path, os.X_OK):
        pytest.skip(f"ESSAIM={path} is not an executable file (build the essaim target)")
    wrapper = tmp_path_factory.mktemp("bin") / "essaim"
    # Not under ASan (ESSAIM_SANITIZED=1): its shadow memory needs terabytes of address space.
    limit = "" if os.environ.get("ESSAIM_SANITIZED") == "1" else "ulimit -v 4194304\n"
    wrapper.write_text(f'#!/bin/sh\n{limit}exec "{os.path.abspath(path)}" "$@"\n')
    wrapper.chmod(0o755)
    return str(wrapper)


def toml_value(v) -> str:
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k} = {toml_value(x)}" for k, x in v.items()) + "}"
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    return json.dumps(v)


def write_sweep(path: Path, experiment: str = "tiny.argos", **keys) -> Path:
    """A sweep file running a test data experiment from the data folder.

    Keyword arguments are top-level keys; `params` and `set` are tables.
    """
    lines = [f"experiment = {json.dumps(str(DATA / experiment))}",
             f"workdir = {json.dumps(str(DATA))}"]
    tables = {k: keys.pop(k) for k in ("params", "set") if k in keys}
    for k, v in keys.items():
        lines.append(f"{k} = {toml_value(v)}")
    for name, table in tables.items():
        lines.append(f"[{name}]")
        for k, v in table.items():
            lines.append(f'"{k}" = {toml_value(v)}')
    path.write_text("\n".join(lines) + "\n")
    return path


def run_sweep(*args, env=None, essaim=None, timeout=120):
    """scripts/sweep.py as a user runs it; returns the CompletedProcess."""
    e = dict(os.environ)
    e.update(env or {})
    if essaim:
        e["ESSAIM"] = essaim
    return subprocess.run([sys.executable, str(SCRIPTS / "sweep.py"), "--no-progress", *map(str, args)],
                          capture_output=True, text=True, timeout=timeout, env=e)


def load_module(name):
    """scripts/<name>.py as a module."""
    import importlib.util
    spec = importlib.util.spec_from_file_location(f"essaim_{name}", SCRIPTS / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod  # dataclasses look their module up there
    spec.loader.exec_module(mod)
    return mod
