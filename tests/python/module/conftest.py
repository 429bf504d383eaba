"""Fixtures for the module and optimiser tests (their paths: module_paths.py). ctest puts
the built module on PYTHONPATH and the essaim executable in $ESSAIM."""
import os

import pytest


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
