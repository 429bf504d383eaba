"""log() lines of `essaim run`: never glued to the progress line on a terminal, --log-prefix
names the tick and the robot, --log-dir writes one file per robot."""
import os
import pty
import subprocess
from pathlib import Path

import pytest

ESSAIM = os.environ.get("ESSAIM")
DATA = Path(__file__).resolve().parents[1] / "data"
pytestmark = pytest.mark.skipif(not ESSAIM, reason="ESSAIM (the essaim binary) is not set")

LOGGER = """
local n = 0
function init() if robot.id == "fb0" then log("ready") end end
function step()
  n = n + 1
  if robot.id == "fb1" and n % 5 == 0 then log("tick " .. n) end
end
"""


def experiment(tmp_path):
    (tmp_path / "logger.lua").write_text(LOGGER)
    text = (DATA / "tiny.argos").read_text().replace('script="tiny.lua"', f'script="{tmp_path}/logger.lua"')
    (tmp_path / "x.argos").write_text(text)
    return tmp_path / "x.argos"


def test_on_a_terminal_the_progress_line_is_cleared_before_a_log_line(tmp_path):
    f = experiment(tmp_path)
    main, sub = pty.openpty()
    p = subprocess.Popen([ESSAIM, "run", str(f), "--ticks", "20", "--out", str(tmp_path / "o")],
                         stdin=subprocess.DEVNULL, stdout=sub, stderr=sub)
    os.close(sub)
    chunks = []
    while True:
        try:
            data = os.read(main, 4096)
        except OSError:  # the pty closes when essaim exits
            break
        if not data:
            break
        chunks.append(data)
    assert p.wait(timeout=60) == 0
    out = b"".join(chunks).decode()
    assert "ticks/s" in out, out  # the progress line was drawn
    for text in ("tick 5", "tick 10", "tick 15", "tick 20"):
        at = out.index(text)
        assert out[at - 1] in "\r\n", repr(out[max(0, at - 80):at + 10])


def test_log_prefix_names_tick_and_robot(tmp_path):
    f = experiment(tmp_path)
    r = subprocess.run([ESSAIM, "run", str(f), "--ticks", "10", "--quiet", "--log-prefix", "--out", str(tmp_path / "o")],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines() == ["[t=0 fb0] ready", "[t=5 fb1] tick 5", "[t=10 fb1] tick 10"]


def test_log_dir_writes_one_file_per_robot(tmp_path):
    f = experiment(tmp_path)
    logs = tmp_path / "logs"
    logs.mkdir()
    (logs / "fb1.log").write_text("an older run's line\n")
    r = subprocess.run([ESSAIM, "run", str(f), "--ticks", "10", "--quiet", "--log-dir", str(logs), "--out", str(tmp_path / "o")],
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    assert r.stdout == ""
    assert (logs / "fb0.log").read_text() == "ready\n"
    assert (logs / "fb1.log").read_text() == "tick 5\ntick 10\n"
    assert not (logs / "fb2.log").exists()


def test_log_dir_keeps_odd_robot_ids_inside_the_folder(tmp_path):
    f = experiment(tmp_path)
    (tmp_path / "logger.lua").write_text('function step() log(robot.id) end\n')
    f.write_text(f.read_text().replace('<foot-bot id="fb">', '<foot-bot id="../fb">'))
    logs = tmp_path / "logs"
    r = subprocess.run([ESSAIM, "run", str(f), "--ticks", "5", "--quiet", "--log-dir", str(logs),
                        "--out", str(tmp_path / "o")], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    assert sorted(p.name for p in logs.iterdir()) == [f"_.._fb{i}~{i}.log" for i in range(4)]
    assert (logs / "_.._fb2~2.log").read_text() == "../fb2\n" * 5
    assert not list(tmp_path.glob("fb*.log"))


def test_robots_added_during_the_run_have_their_own_log_file_and_prefix(tmp_path):
    f = experiment(tmp_path)
    (tmp_path / "logger.lua").write_text('function init() log("hello ", robot.id) end\nfunction step() end\n')
    (tmp_path / "loop.lua").write_text(
        'function post_step()\n'
        '  if experiment.tick == 3 then experiment.add_entity("foot-bot", {id = "late", controller = "ctrl",'
        ' position = {0, 1.9}}) end\n'
        'end\n')
    f.write_text(f.read_text().replace("<arena ", f'<loop_functions script="{tmp_path}/loop.lua"/>\n  <arena '))
    logs = tmp_path / "logs"
    r = subprocess.run([ESSAIM, "run", str(f), "--ticks", "5", "--quiet", "--log-dir", str(logs),
                        "--out", str(tmp_path / "o")], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    assert (logs / "late.log").read_text() == "hello late\n"
    assert (logs / "fb3.log").read_text() == "hello fb3\n"
    r = subprocess.run([ESSAIM, "run", str(f), "--ticks", "5", "--quiet", "--log-prefix",
                        "--out", str(tmp_path / "p")], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines()[-1] == "[t=3 late] hello late"
