"""Every example in README.md and docs/*.md runs as written (doc_examples.py says what an
example is and how a block is marked illustrative or shortened). Each file's examples run
in order, in a fresh copy of the repository's arenas, controllers, scripts and docs, set up
as scripts/setup.sh leaves a checkout (sandbox() says how), so a command may use what an
earlier one made. The environment is the user's: no ESSAIM, no PYTHONPATH, and no `essaim`
on PATH but the link the set-up made. docs/tutorial.md is one of them."""
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from doc_examples import examples

ROOT = Path(__file__).resolve().parents[2]
DOCS = ["README.md"] + sorted(str(p.relative_to(ROOT)) for p in (ROOT / "docs").glob("*.md"))
COPIED = ("arenas", "controllers", "scripts", "tools", "docs", "bench")
TIMEOUT = 300  # seconds per block
SIERRA_VENV = ROOT / ".venv-sierra"


@pytest.fixture(scope="module")
def essaim():
    path = os.environ.get("ESSAIM")
    if not path or not os.access(path, os.X_OK):
        pytest.skip("ESSAIM is not set to the essaim executable (ctest sets it)")
    return Path(path).resolve()


def sandbox(tmp: Path, essaim: Path) -> dict:
    """The copy the examples run in, as scripts/setup.sh leaves a checkout: build/ is the
    build under test, .venv a venv with the suite's packages (setup.sh installs them from
    PyPI; here they are the suite's own), and the set-up's last step, scripts/link_build.sh,
    links `essaim` into a folder on PATH (standing for ~/.local/bin) and writes .venv's .pth
    for `import essaim`. Returns the environment the examples run in."""
    for d in COPIED:
        shutil.copytree(ROOT / d, tmp / d, symlinks=True)
    (tmp / "build").symlink_to(essaim.parent)
    make_venv(tmp / ".venv")
    if SIERRA_VENV.exists():  # SIERRA's own venv (docs/sierra.md), as setup_sierra.sh makes it
        (tmp / ".venv-sierra").symlink_to(SIERRA_VENV)
    bin_dir = tmp / "home" / ".local" / "bin"
    env = users_env(bin_dir)
    r = subprocess.run(["bash", "scripts/link_build.sh", str(bin_dir)], cwd=tmp, env=env,
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    return env


def make_venv(folder: Path) -> None:
    """A venv as setup.sh makes one; its packages are those of the suite's interpreter."""
    import sysconfig
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(folder)], check=True, timeout=120)
    site = subprocess.run([str(folder / "bin" / "python3"), "-c",
                           "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                          check=True, capture_output=True, text=True, timeout=60).stdout.strip()
    packages = sysconfig.get_paths()["purelib"]
    Path(site, "suite-packages.pth").write_text(f"import site; site.addsitedir({packages!r})\n")


def users_env(bin_dir: Path) -> dict:
    """The environment a user's shell has: PATH without any other `essaim` (ctest's, or one
    an earlier set-up linked) but with bin_dir first, and none of the suite's variables."""
    path = [d for d in os.environ.get("PATH", "").split(":") if d and not (Path(d) / "essaim").exists()]
    env = {k: v for k, v in os.environ.items()
           if k not in ("ESSAIM", "PYTHONPATH", "ESSAIM_SANITIZED", "MPLBACKEND")}
    env["PATH"] = ":".join([str(bin_dir), *path])
    return env


def run_block(ex, cwd: Path, env: dict, n: int) -> None:
    text = ex.runnable()
    for cmd in ex.before:
        run_checked(["bash", "-e", "-o", "pipefail", "-c", cmd], ex, cmd, cwd, env)
    if ex.lang == "python":
        script = cwd / f".example-{n}.py"
        script.write_text(text)
        argv = [str(cwd / ".venv" / "bin" / "python"), str(script)]
    else:
        argv = ["bash", "-e", "-o", "pipefail", "-c", text]
    run_checked(argv, ex, text, cwd, env)


def run_checked(argv, ex, text, cwd, env):
    try:
        r = subprocess.run(argv, cwd=cwd, env=env, capture_output=True, text=True,
                           timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        pytest.fail(f"{ex.where}: still running after {TIMEOUT} s:\n{text}")
    if r.returncode != 0:
        pytest.fail(f"{ex.where}: exit {r.returncode}:\n{text}\n--- stdout\n{r.stdout[-3000:]}"
                    f"\n--- stderr\n{r.stderr[-3000:]}")


@pytest.mark.parametrize("doc", DOCS)
def test_examples_run_as_written(doc, tmp_path, essaim):
    found = examples(ROOT / doc, ROOT)
    if not found:
        pytest.skip(f"{doc} has no example")
    if doc == "docs/sierra.md" and not (SIERRA_VENV / "bin" / "sierra").exists():
        pytest.skip(f"SIERRA is not installed in {SIERRA_VENV} (scripts/setup_sierra.sh makes it)")
    env = sandbox(tmp_path, essaim)
    for n, ex in enumerate(found):
        if not ex.skip:
            run_block(ex, tmp_path, env, n)


def test_few_examples_are_left_out_and_each_says_why():
    skipped = [ex for doc in DOCS for ex in examples(ROOT / doc, ROOT) if ex.skip]
    # 13: installs, sanitizer and fuzz runs, a Dask cluster, SLURM, and the three blocks of
    # `serve` / `run --watch`, which run until Ctrl-C (the live test drives them).
    assert len(skipped) <= 13, [ex.where for ex in skipped]
    for ex in skipped:
        assert len(ex.skip) > 15, f"{ex.where}: say why it is not run"


def test_the_extractor_tells_examples_from_output_and_synopses(tmp_path):
    (tmp_path / "d.md").write_text(
        "```\nessaim run a.argos\n```\n"
        "```\nsweep: 4 runs ok\n```\n"
        "```\nessaim run FILE.argos [--ticks N]\n```\n"
        "<!-- doc-test: skip: needs a Dask cluster running -->\n```\nessaim devices\n```\n"
        "<!-- doc-test: replace --ticks 5000 => --ticks 5 -->\n"
        "<!-- doc-test: before: echo hi -->\n```sh\nessaim run b.argos --ticks 5000\n```\n"
        "```python\nprint(1)\n```\n```toml\nx = 1\n```\n")
    found = examples(tmp_path / "d.md", tmp_path)
    assert [(e.line, e.lang) for e in found] == [(1, "shell"), (11, "shell"), (16, "shell"),
                                                 (19, "python")]
    assert found[1].skip == "needs a Dask cluster running"
    assert found[2].runnable() == "essaim run b.argos --ticks 5\n"
    assert found[2].before == ["echo hi"]


def test_the_setups_link_puts_essaim_on_path_and_leaves_others_alone(tmp_path, essaim):
    (tmp_path / "scripts").mkdir()
    shutil.copy(ROOT / "scripts" / "link_build.sh", tmp_path / "scripts")
    (tmp_path / "build").symlink_to(essaim.parent)
    bin_dir = tmp_path / "bin"
    env = users_env(bin_dir)
    for _ in range(2):  # idempotent, as setup.sh is
        r = subprocess.run(["bash", "scripts/link_build.sh", str(bin_dir)], cwd=tmp_path, env=env,
                           capture_output=True, text=True, timeout=60)
        assert r.returncode == 0, r.stderr
    assert (bin_dir / "essaim").resolve() == essaim
    r = subprocess.run(["bash", "-c", "essaim --version"], cwd=tmp_path, env=env, capture_output=True,
                       text=True, timeout=60)
    assert r.returncode == 0 and "essaim" in r.stdout, r.stderr
    # Not on PATH: said, with what to do.
    r = subprocess.run(["bash", "scripts/link_build.sh", str(tmp_path / "elsewhere")], cwd=tmp_path,
                       env=env, capture_output=True, text=True, timeout=60)
    assert f"{tmp_path / 'elsewhere'} is not on PATH; add it" in r.stdout
    # An essaim installed there another way (a file, not a link) stays.
    (bin_dir / "essaim").unlink()
    (bin_dir / "essaim").write_text("#!/bin/sh\n")
    r = subprocess.run(["bash", "scripts/link_build.sh", str(bin_dir)], cwd=tmp_path, env=env,
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 0 and "is a file, not a link: left as it is" in r.stderr
    assert (bin_dir / "essaim").read_text() == "#!/bin/sh\n"
