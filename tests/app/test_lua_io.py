"""Lua's io library through `essaim run`: io.write follows io.output, so a controller's own
files fill and only what goes to io.stdout is printed (with --log-prefix, into --log-dir);
under --sandbox there is no io and the error says so. Files are opened by absolute paths
(robot.params.dir), whatever the run's working folder."""
import pytest

from clitest import argos, essaim, need_essaim, write

pytestmark = need_essaim

# The reproduction, with the folder from the controller's params.
REPRODUCTION = """
function init()
  local f = io.open(robot.params.dir .. "/out_" .. robot.id .. ".txt", "w")
  io.output(f)
  io.write("hello from ", robot.id, "\\n")
  io.close(f)
  io.output(io.stdout)
end
function step() end
"""

# A learning log by name, then back to stdout: one line a tick to the file, one printed.
BY_NAME = """
local n = 0
function init() io.output(robot.params.dir .. "/rewards_" .. robot.id .. ".lua") end
function step()
  n = n + 1
  if n <= 3 then
    io.write("reward[", n, "] = ", n / 2, "\\n")
  elseif n == 4 then
    io.close()
    io.output(io.stdout)
    io.write("closed after ", n - 1, " rewards\\n")
  end
end
"""


def experiment(tmp_path, script, robots=2, length=1):
    write(tmp_path, {"x.argos": argos(robots=robots, length=length, params=f'dir="{tmp_path}"'), "c.lua": script})


@pytest.mark.parametrize("threads", [1, 2])
def test_the_files_fill_and_nothing_is_printed(tmp_path, threads):
    experiment(tmp_path, REPRODUCTION, robots=3)
    r = essaim("run", "x.argos", "--ticks", "2", "--threads", threads, "--out", "o", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    for i in range(3):
        assert (tmp_path / f"out_fb{i}.txt").read_text() == f"hello from fb{i}\n"
    assert "hello" not in r.stdout + r.stderr


@pytest.mark.parametrize("threads", [1, 2])
def test_output_by_name_then_stdout_with_log_prefix(tmp_path, threads):
    experiment(tmp_path, BY_NAME, robots=3)
    r = essaim("run", "x.argos", "--ticks", "6", "--threads", threads, "-q", "--log-prefix", "--out", "o",
               cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    for i in range(3):
        text = (tmp_path / f"rewards_fb{i}.lua").read_text()
        assert text == "reward[1] = 0.5\nreward[2] = 1\nreward[3] = 1.5\n", text
    assert r.stdout.splitlines() == [f"[t=4 fb{i}] closed after 3 rewards" for i in range(3)], r.stdout


@pytest.mark.parametrize("threads", [1, 2])
def test_log_dir_gets_only_what_goes_to_stdout(tmp_path, threads):
    experiment(tmp_path, BY_NAME, robots=2)
    logs = tmp_path / "logs"
    r = essaim("run", "x.argos", "--ticks", "6", "--threads", threads, "-q", "--log-dir", logs, "--out", "o",
               cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert r.stdout == ""
    for i in range(2):
        assert (logs / f"fb{i}.log").read_text() == "closed after 3 rewards\n"
        assert (tmp_path / f"rewards_fb{i}.lua").read_text().count("\n") == 3


def test_loop_functions_files_fill_too(tmp_path):
    loop = ('function init()\n'
            '  io.output(experiment.params.dir .. "/loop.txt")\n'
            '  io.write("robots ", #experiment.robots, "\\n")\n'
            '  io.close()\n'
            '  io.output(io.stdout)\n'
            '  io.write("loop ready\\n")\n'
            'end\n')
    write(tmp_path, {"x.argos": argos(robots=2, loop=f'<loop_functions script="loop.lua" dir="{tmp_path}"/>'),
                     "c.lua": "function step() end\n", "loop.lua": loop})
    logs = tmp_path / "logs"
    r = essaim("run", "x.argos", "--ticks", "1", "-q", "--log-dir", logs, "--out", "o", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "loop.txt").read_text() == "robots 2\n"
    assert (logs / "loop_functions.log").read_text() == "loop ready\n"


def test_under_the_sandbox_writing_is_refused_with_the_sandboxs_message(tmp_path):
    experiment(tmp_path, REPRODUCTION, robots=1)
    r = essaim("run", "x.argos", "--ticks", "2", "-q", "--sandbox", "--out", "o", cwd=tmp_path)
    assert r.returncode == 0, r.stderr  # one robot stopped; the run goes on
    assert "c.lua:3: attempt to index a nil value (global 'io')" in r.stderr, r.stderr
    assert "--sandbox leaves out io, os, debug, dofile and loadfile" in r.stderr, r.stderr
    assert not list(tmp_path.glob("out_*.txt"))
