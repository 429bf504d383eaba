"""Every example printed by `essaim COMMAND --help` runs as written, in the order the
commands are listed (the snapshot example draws the run example's recording), from a folder
that holds the repository's arenas/, controllers/ and bench/ like a checkout does. An example
that runs until interrupted says "Ctrl-C" on its line: it must still be running after a few
seconds, and end cleanly on SIGINT."""
import os
import re
import signal
import subprocess

import pytest

from clitest import ESSAIM, ROOT, need_essaim

pytestmark = need_essaim


def help_text(*args):
    r = subprocess.run([ESSAIM, *args, "--help"], capture_output=True, text=True, timeout=30)
    assert r.returncode == 0, r.stderr
    return r.stdout


def commands():
    listed = help_text().split("Subcommands:")[1].split("\n\n")[0]
    return [line.split()[0] for line in listed.strip().splitlines() if line.split()[0] != "help"]


def examples(text):
    """The indented lines under each "Example..." heading."""
    found, inside = [], False
    for line in text.splitlines():
        if line.startswith("Example"):
            inside = True
        elif inside and line.startswith("  ") and line.strip():
            found.append(line.strip())
        else:
            inside = False
    return found


@pytest.fixture(scope="module")
def checkout(tmp_path_factory):
    folder = tmp_path_factory.mktemp("checkout")
    for name in ("arenas", "controllers", "bench"):
        (folder / name).symlink_to(ROOT / name)
    bin_dir = tmp_path_factory.mktemp("bin")
    (bin_dir / "essaim").symlink_to(os.path.abspath(ESSAIM))
    env = dict(os.environ, PATH=f"{bin_dir}:{os.environ['PATH']}", PAGER="cat", LESS="-FX")
    return folder, env


def run_until_interrupted(example, folder, env):
    p = subprocess.Popen(["bash", "-c", "exec " + example.split("#")[0]], cwd=folder, env=env,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, stdin=subprocess.DEVNULL)
    try:
        out, err = p.communicate(timeout=3)
        pytest.fail(f"{example}: ended at once (exit {p.returncode})\n{out[-2000:]}\n{err[-2000:]}")
    except subprocess.TimeoutExpired:
        p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=30)
        assert p.returncode in (0, 130), f"{example}: exit {p.returncode} on SIGINT\n{err[-2000:]}"


def test_every_command_has_an_example():
    for command in commands():
        assert examples(help_text(command)), f"essaim {command} --help shows no example"


def test_every_help_example_runs_as_written(checkout):
    folder, env = checkout
    ran = []
    for command in commands():
        for example in examples(help_text(command)):
            assert re.match(r"(source <\()?essaim ", example), example
            if "Ctrl-C" in example:
                run_until_interrupted(example, folder, env)
            else:
                r = subprocess.run(["bash", "-c", "set -o pipefail; " + example], cwd=folder, env=env,
                                   capture_output=True, text=True, timeout=120, stdin=subprocess.DEVNULL)
                assert r.returncode == 0, f"{example}\n{r.stdout[-2000:]}\n{r.stderr[-2000:]}"
            ran.append(example)
    assert any(e.startswith("essaim run ") for e in ran)
    assert (folder / "runs/foraging-7/summary.json").exists() and (folder / "tick500.png").exists()
    assert (folder / "runs/f/replay.html").exists()
