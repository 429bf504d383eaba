"""Outputs never stale, never misplaced, never lost in silence (docs/cli.md "The
output folder"): a reused --out folder holds only the new run's outputs; a wrong --out is bad
input before anything runs; a full disk ends with what could be written and exit 1;
replay/snapshot -o refuse what is not a regular file; loop-function init() errors exit 1;
timeseries.csv is RFC 4180 with NaN/Inf warned once."""
import csv
import io
import json
import os
import resource
import shutil
import signal
import stat
import subprocess
from pathlib import Path

import pytest

ESSAIM = os.environ.get("ESSAIM")
DATA = Path(__file__).resolve().parents[1] / "data"
pytestmark = pytest.mark.skipif(not ESSAIM, reason="ESSAIM (the essaim binary) is not set")


def run(*args, cwd=None, preexec_fn=None):
    return subprocess.run([ESSAIM, *map(str, args)], capture_output=True, text=True, timeout=60, cwd=cwd,
                          preexec_fn=preexec_fn)


def loop_experiment(tmp_path, loop_lua):
    """tiny_loop.argos in tmp_path with loop functions `loop_lua`; returns the .argos path."""
    shutil.copy(DATA / "tiny.lua", tmp_path / "tiny.lua")
    (tmp_path / "loop.lua").write_text(loop_lua)
    argos = (DATA / "tiny_loop.argos").read_text().replace('script="tiny_loop.lua"', 'script="loop.lua"')
    (tmp_path / "x.argos").write_text(argos)
    return tmp_path / "x.argos"


def summary(folder):
    return json.loads((folder / "summary.json").read_text())


# ---- a reused --out folder ----------------------------------------------------------

def test_reused_out_folder_moves_the_earlier_runs_outputs_into_previous(tmp_path):
    exp, out = loop_experiment(tmp_path, (DATA / "tiny_loop.lua").read_text()), tmp_path / "o"
    r = run("run", exp, "--ticks", 5, "--quiet", "--record", "--out", out, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert run("replay", out).returncode == 0
    (out / "notes.txt").write_text("mine")  # not essaim's: stays

    r = run("run", exp, "--ticks", 3, "--quiet", "--out", out, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert "held an earlier run's outputs; moved them into" in r.stderr
    assert "metrics.json, recording.bin, replay.html, summary.json" in r.stderr
    assert sorted(p.name for p in out.iterdir()) == ["metrics.json", "notes.txt", "previous", "summary.json"]
    assert summary(out)["ticks"] == 3 and summary(out / "previous")["ticks"] == 5
    assert (out / "previous" / "recording.bin").is_file()
    # No stale recording to replay: the folder's recording is the run's or none.
    stale = run("replay", out)
    assert stale.returncode == 2 and "no recording" in stale.stderr

    # previous/ holds one earlier run, not a mix: the 5-tick run moves on to previous-2/, whole.
    r = run("run", exp, "--ticks", 4, "--quiet", "--out", out, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert sorted(p.name for p in (out / "previous").iterdir()) == ["metrics.json", "summary.json"]
    assert summary(out / "previous")["ticks"] == 3 and summary(out)["ticks"] == 4
    assert summary(out / "previous-2")["ticks"] == 5 and (out / "previous-2" / "recording.bin").is_file()


def test_a_fresh_folder_gets_no_note(tmp_path):
    r = run("run", DATA / "tiny.argos", "--ticks", 2, "--quiet", "--out", tmp_path / "new", cwd=DATA)
    assert r.returncode == 0, r.stderr
    assert r.stderr == "" and not (tmp_path / "new" / "previous").exists()


# ---- a wrong --out -----------------------------------------------------------------

def _unwritable_folder(tmp_path):
    if os.geteuid() != 0:
        d = tmp_path / "ro"
        d.mkdir()
        d.chmod(0o500)
        return d
    for candidate in ("/sys/kernel", "/proc/self"):  # root writes anywhere else
        try:
            open(os.path.join(candidate, "essaim-probe"), "w").close()
        except OSError:
            return Path(candidate)
        os.remove(os.path.join(candidate, "essaim-probe"))
    pytest.skip("no folder here that root cannot write")


@pytest.mark.parametrize("kind", ["file", "unwritable", "uncreatable"])
def test_a_wrong_out_is_bad_input_before_any_script_runs(tmp_path, kind):
    ran = tmp_path / "ran"
    exp = loop_experiment(tmp_path, f"io.open({json.dumps(str(ran))}, 'w'):close()\n")
    if kind == "file":
        out = tmp_path / "a-file"
        out.write_text("x")
        message = "is a file, not a folder"
    elif kind == "unwritable":
        out = _unwritable_folder(tmp_path)
        message = "cannot write in this folder"
    else:
        (tmp_path / "f").write_text("x")
        out = tmp_path / "f" / "sub"
        message = "cannot create the folder"
    r = run("run", exp, "--ticks", 2, "--quiet", "--out", out, cwd=tmp_path)
    assert r.returncode == 2, r.stderr
    assert f"--out {out}" in r.stderr and message in r.stderr
    assert not ran.exists()  # checked before the loop functions' top level ran


# ---- a full disk --------------------------------------------------------------------

def _file_size_limit(limit):
    """A file-size cap (RLIMIT_FSIZE) with SIGXFSZ ignored: writes past it fail with EFBIG,
    as on a full disk, without a loop device or root."""
    def apply():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
    return apply


def test_a_recording_too_big_for_the_disk_leaves_the_other_outputs_and_exit_1(tmp_path):
    exp, out = loop_experiment(tmp_path, (DATA / "tiny_loop.lua").read_text()), tmp_path / "o"
    r = run("run", exp, "--ticks", 3000, "--quiet", "--record", "--out", out, cwd=tmp_path,
            preexec_fn=_file_size_limit(16384))
    assert r.returncode == 1, r.stderr
    assert "cannot write" in r.stderr and "recording.bin: File too large" in r.stderr
    s = summary(out)
    assert s["status"] == "failed" and s["ticks"] == 3000
    assert "recording.bin: File too large" in s["failure"]
    assert s["outputs"] == ["summary.json", "metrics.json"]
    assert sorted(p.name for p in out.iterdir()) == ["metrics.json", "summary.json"]  # no temporary left


def test_a_disk_with_no_room_at_all_says_so_and_exits_1(tmp_path):
    out = tmp_path / "o"
    r = run("run", DATA / "tiny.argos", "--ticks", 3, "--quiet", "--out", out, cwd=DATA,
            preexec_fn=_file_size_limit(0))
    assert r.returncode == 1, r.stderr
    assert "summary.json: File too large" in r.stderr and f"the outputs in {out} are incomplete" in r.stderr
    assert list(out.iterdir()) == []


# ---- replay -o and snapshot -o ------------------------------------------------------

@pytest.fixture(scope="module")
def recorded(tmp_path_factory):
    out = tmp_path_factory.mktemp("rec") / "run"
    r = run("run", DATA / "tiny.argos", "--ticks", 10, "--quiet", "--record", "--out", out, cwd=DATA)
    assert r.returncode == 0, r.stderr
    return out


def _target(tmp_path, kind):
    t = tmp_path / "target"
    if kind == "fifo":
        os.mkfifo(t)
    elif kind == "device":
        if os.geteuid() != 0:
            pytest.skip("making a device file needs root")
        os.mknod(t, 0o600 | stat.S_IFCHR, os.makedev(1, 3))  # like /dev/null
    elif kind == "folder":
        t.mkdir()
    elif kind == "dangling symlink":
        t.symlink_to(tmp_path / "nowhere" / "x")
    elif kind == "symlink to a FIFO":
        os.mkfifo(tmp_path / "fifo")
        t.symlink_to(tmp_path / "fifo")
    return t


@pytest.mark.parametrize("command", ["replay", "snapshot"])
@pytest.mark.parametrize("kind, message", [
    ("fifo", "it is a FIFO, not a regular file"),
    ("device", "it is a character device, not a regular file"),
    ("folder", "it is a folder, not a regular file"),
    ("dangling symlink", "a symlink whose target cannot be reached"),
    ("symlink to a FIFO", "it is a FIFO, not a regular file"),
])
def test_an_output_that_is_not_a_regular_file_is_refused(recorded, tmp_path, command, kind, message):
    t = _target(tmp_path, kind)
    before = os.lstat(t)
    r = run(command, recorded, "-o", t)
    if command == "snapshot" and "without Cairo" in r.stderr:
        pytest.skip("built without Cairo")
    assert r.returncode == 2, r.stderr
    assert f"cannot write {t}: {message}" in r.stderr
    after = os.lstat(t)
    assert (after.st_mode, after.st_ino) == (before.st_mode, before.st_ino)  # untouched


@pytest.mark.parametrize("command, magic", [("replay", b"<!doctype html>"), ("snapshot", b"\x89PNG")])
def test_an_output_symlink_is_written_through(recorded, tmp_path, command, magic):
    real = tmp_path / "real"
    real.write_text("old")
    link = tmp_path / "link"
    link.symlink_to(real)
    r = run(command, recorded, "-o", link)
    if command == "snapshot" and "without Cairo" in r.stderr:
        pytest.skip("built without Cairo")
    assert r.returncode == 0, r.stderr
    assert link.is_symlink() and os.readlink(link) == str(real)
    assert real.read_bytes().startswith(magic)


def test_an_output_in_a_missing_folder_is_bad_input(recorded, tmp_path):
    r = run("replay", recorded, "-o", tmp_path / "no" / "page.html")
    assert r.returncode == 2 and "no folder" in r.stderr


# ---- summary.json: where the set-up time went -----------------------------------------

def test_summary_reports_setup_seconds_in_the_stage_that_spent_them(tmp_path):
    # Each of the 4 robots' states spends 0.1 s CPU in its script's top level and 0.2 s in
    # init(): about 0.4 s and 0.8 s of wall clock, in `lua_states` and `init`. os.clock() is
    # the whole process's CPU time, so the run's other threads shorten each spin a little:
    # a 10 % margin.
    (tmp_path / "slow.lua").write_text(
        "local function spin(s) local t = os.clock() while os.clock() - t < s do end end\n"
        "spin(0.1)\n"
        "function init() spin(0.2) end\n"
        "function step() robot.wheels.set_velocity(1, 1) end\n")
    (tmp_path / "x.argos").write_text((DATA / "tiny.argos").read_text().replace('script="tiny.lua"',
                                                                                'script="slow.lua"'))
    r = run("run", tmp_path / "x.argos", "--ticks", 2, "--threads", 1, "--quiet", "--out", tmp_path / "o",
            cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    s = summary(tmp_path / "o")
    setup = s["setup_seconds"]
    assert list(setup) == ["load", "placement", "world", "lua_states", "init", "total"]
    assert all(v >= 0 for v in setup.values())
    assert setup["lua_states"] >= 0.36 and setup["init"] >= 0.72
    parts = sum(v for k, v in setup.items() if k != "total")
    assert abs(setup["total"] - parts) < 1e-9
    # wall_seconds counts from the world's set-up on (the load and placement come before).
    assert s["wall_seconds"] >= setup["world"] + setup["lua_states"] + setup["init"]
    assert list(s)[list(s).index("stage_seconds") + 1] == "setup_seconds"


# ---- loop functions: init() errors, timeseries.csv ----------------------------------

def test_an_error_in_loop_function_init_is_a_failed_run_exit_1_with_a_summary(tmp_path):
    exp = loop_experiment(tmp_path, "function init()\n  error('no food here')\nend\n")
    r = run("run", exp, "--ticks", 5, "--quiet", "--out", tmp_path / "o", cwd=tmp_path)
    assert r.returncode == 1, r.stderr
    assert "loop functions (init): " in r.stderr and "loop.lua:2: no food here" in r.stderr
    s = summary(tmp_path / "o")
    assert s["status"] == "failed" and s["ticks"] == 0 and "no food here" in s["failure"]
    c = run("check", exp, cwd=tmp_path)  # check: anything wrong is exit 2
    assert c.returncode == 2 and "no food here" in c.stderr
    # A syntax error is still bad input (exit 2): nothing ran, and the summary says why.
    exp = loop_experiment(tmp_path, "function init(\n")
    r = run("run", exp, "--ticks", 5, "--quiet", "--out", tmp_path / "p", cwd=tmp_path)
    assert r.returncode == 2 and summary(tmp_path / "p")["status"] == "failed"


def test_timeseries_csv_quotes_names_and_warns_once_about_nan(tmp_path):
    exp = loop_experiment(tmp_path, """
function post_step()
  local t = experiment.tick
  experiment.timeseries({{"tick", t}, {"a,b", t == 2 and 0/0 or 1}, {'say "hi"', -1/0},
                         {"two\\nlines", 0.5}, {"nul\\0x", 1/0}, {7, 3}})
end
""")
    r = run("run", exp, "--ticks", 3, "--quiet", "--out", tmp_path / "o", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    text = (tmp_path / "o" / "timeseries.csv").read_text()
    rows = list(csv.reader(io.StringIO(text, newline="")))
    assert rows[0] == ["tick", "a,b", 'say "hi"', "two\nlines", "nul\0x", "7"]
    assert rows[1:] == [["1", "1", "-Inf", "0.5", "Inf", "3"], ["2", "NaN", "-Inf", "0.5", "Inf", "3"],
                        ["3", "1", "-Inf", "0.5", "Inf", "3"]]
    assert float(rows[2][1]) != float(rows[2][1]) and float(rows[1][2]) == float("-inf")
    warnings = [line for line in r.stderr.splitlines() if "timeseries(): NaN or infinite" in line]
    assert len(warnings) == 1 and "column 'say \"hi\"' at tick 1" in warnings[0]


def test_a_bad_timeseries_row_leaves_no_half_row(tmp_path):
    # The error is raised in the middle of a row: the columns and rows written stay whole.
    exp = loop_experiment(tmp_path, """
function post_step()
  if experiment.tick == 1 then experiment.timeseries({{"a", 1}, {"b", 2}}) end
  if experiment.tick == 2 then pcall(experiment.timeseries, {{"a", 3}, {"b", "x"}}) end
  if experiment.tick == 3 then pcall(experiment.timeseries, {{"a", 4}, {"c", 5}}) end
  if experiment.tick == 4 then experiment.timeseries({{"a", 6}, {"b", 7}}) end
end
""")
    r = run("run", exp, "--ticks", 4, "--quiet", "--out", tmp_path / "o", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "o" / "timeseries.csv").read_text() == "a,b\n1,2\n6,7\n"


def test_deeply_nested_metrics_are_written_or_refused_cleanly(tmp_path):
    # The conversion runs outside any pcall and uses a few stack slots per level.
    exp = loop_experiment(tmp_path, """
function post_experiment()
  local depth = tonumber(experiment.params.depth)
  local t = {leaf = 1, list = {1, 2}}
  for i = 1, depth do t = {a = t, b = {x = i}, c = {t}} end
  return t
end
""")
    argos = exp.read_text().replace('script="loop.lua"', 'script="loop.lua" depth="14"')
    exp.write_text(argos)
    r = run("run", exp, "--ticks", 1, "--quiet", "--out", tmp_path / "o", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    m = json.loads((tmp_path / "o" / "metrics.json").read_text())
    for _ in range(14):
        m = m["a"]
    assert m == {"leaf": 1, "list": [1, 2]}
    exp.write_text(argos.replace('depth="14"', 'depth="40"'))
    r = run("run", exp, "--ticks", 1, "--quiet", "--out", tmp_path / "p", cwd=tmp_path)
    assert r.returncode == 1 and "nested too deep" in r.stderr
    assert summary(tmp_path / "p")["status"] == "failed"
