"""Shared paths for the module and optimiser tests. ctest puts the built module on
PYTHONPATH and the essaim executable in $ESSAIM."""
import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
FORAGING = str(ROOT / "arenas" / "foraging.argos")
SMALL = {"arena.distribute.entity.quantity": 5}  # a fast variant of the report's arena


@pytest.fixture(scope="session")
def essaim_bin(tmp_path_factory):
    path = os.environ.get("ESSAIM")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("ESSAIM is not set to the essaim executable (ctest sets it)")
    if os.environ.get("LD_PRELOAD"):
        # Sanitizer build: the ASan runtime preloaded for this interpreter must not reach
        # the executable, which has its own linked in.
        wrapper = tmp_path_factory.mktemp("bin") / "essaim"
        wrapper.write_text(f'#!/bin/sh\nunset LD_PRELOAD\nexec "{os.path.abspath(path)}" "$@"\n')
        wrapper.chmod(0o755)
        return str(wrapper)
    return path
