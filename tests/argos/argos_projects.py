"""Helpers for the C++ loop-function tests: the essaim binary ($ESSAIM, set by ctest), the
build tree's ARGoS SDK beside it, and an ARGoS loop-function project built into a folder."""
import os
import shutil
import subprocess
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
ESSAIM = os.environ.get("ESSAIM")
need_essaim = pytest.mark.skipif(not ESSAIM, reason="ESSAIM (the essaim binary) is not set")


def sdk() -> Path:
    """build/argos3-sdk: the libraries, argos3_simulator.pc, ARGoSConfig.cmake."""
    return Path(ESSAIM).resolve().parent / "argos3-sdk"


def build_project(source: Path, folder: Path, prefix: Path = None, cmake_args=(), env=None) -> Path:
    """Copies the project `source` into `folder`, configures and builds it there (its own
    CMakeLists.txt, untouched, and `cmake_args`) with PKG_CONFIG_PATH and CMAKE_PREFIX_PATH
    naming `prefix` (default: the build tree's SDK) and `env` added; returns the copy's folder
    (libraries in its build/)."""
    copy = folder / source.name
    shutil.copytree(source, copy)
    prefix = prefix or sdk()
    env = dict(os.environ, PKG_CONFIG_PATH=str(prefix / "lib" / "pkgconfig"), CMAKE_PREFIX_PATH=str(prefix),
               **(env or {}))
    env.pop("CXXFLAGS", None)
    generator = ["-G", "Ninja"] if shutil.which("ninja") else []
    for command in (["cmake", "-S", ".", "-B", "build", *generator, *cmake_args], ["cmake", "--build", "build"]):
        done = subprocess.run(command, cwd=copy, env=env, capture_output=True, text=True)
        assert done.returncode == 0, f"{' '.join(command)}:\n{done.stdout}\n{done.stderr}"
    return copy


def run(argos: Path, *args, cwd: Path, env=None):
    """essaim run on `argos` from `cwd`; the completed process."""
    return subprocess.run([ESSAIM, "run", str(argos), *args], cwd=cwd, capture_output=True, text=True,
                          env=dict(os.environ, **(env or {})), timeout=300)


def skip_without_python_module():
    """Skips the calling test when the Python module is not built, or under ASan (where the
    interpreter needs the sanitizer's runtime preloaded: python_module covers the module)."""
    if not any((Path(ESSAIM).resolve().parent / "python").glob("essaim*.so")):
        pytest.skip("the Python module is not built")
    if os.environ.get("ESSAIM_SANITIZED") == "1":
        pytest.skip("under ASan the interpreter needs its runtime preloaded: python_module covers the module there")
