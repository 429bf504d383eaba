"""log() separates its arguments with tabs; io.write output is a log line with the robot's
prefix; `essaim devices` lists what every controller has beside its devices."""
from clitest import argos, essaim, need_essaim, write

pytestmark = need_essaim

LOGGER = """
function init()
  log("hello", 1, 2.5, true)
  io.write("written ", 3, "\\n", "open ")
  io.write("line")
end
function step() end
"""


def test_log_tabs_and_io_write_prefix(tmp_path):
    write(tmp_path, {"x.argos": argos(robots=2), "c.lua": LOGGER})
    r = essaim("run", "x.argos", "--ticks", "1", "--log-prefix", "--out", "o", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    lines = [l for l in r.stdout.splitlines() if l.startswith("[t=")]
    assert lines == ["[t=0 fb0] hello\t1\t2.5\t1", "[t=0 fb0] written 3", "[t=0 fb0] open line",
                     "[t=0 fb1] hello\t1\t2.5\t1", "[t=0 fb1] written 3", "[t=0 fb1] open line"], r.stdout


def test_devices_lists_what_every_controller_has():
    out = essaim("devices").stdout
    for name in ("robot.id", "robot.params", "robot.random", "log(...)"):
        assert name in out, name
    assert out.index("robot.id") < out.index("ACTUATORS")
