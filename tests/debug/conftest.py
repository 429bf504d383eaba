"""Fixtures of the `essaim debug` tests: sessions that are killed at the test's end whatever
happened, and the shipped foraging experiment copied into the test's folder."""
import pytest

from dap_client import DapClient
from debug_support import foraging_copy


@pytest.fixture
def argos(tmp_path):
    """A copy of arenas/foraging.argos (with its loop functions and controllers/)."""
    return foraging_copy(tmp_path)


@pytest.fixture
def session(essaim, tmp_path):
    """session(args, tcp=False): an `essaim debug ARGS` session in the test's folder, over
    stdio or over --port; killed at the end of the test if still running."""
    started = []

    def start(args=(), tcp=False, **kw):
        client = (DapClient.tcp if tcp else DapClient.stdio)(essaim, args, cwd=tmp_path, **kw)
        started.append(client)
        return client

    yield start
    for client in started:
        client.kill()
