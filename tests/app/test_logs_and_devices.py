"""log() and logerr() write their arguments as ARGoS does (no separator), print() as Lua does
(tabs); io.write output is a log line with the robot's prefix; `essaim devices` lists what
every controller has beside its devices."""
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

# ARGoS's own texts: arguments one after the other, numbers as a C++ stream writes them
# (6 significant digits), booleans 1/0, other values by type name.
ARGOS_LOG = """
function init()
  log("a", 1, true, 2.5, nil, 1e8, 0.1 + 0.2, 1/3, false, "z")
  logerr("e", 7, " ", 0.5)
  print("p", 1, 2.5, true, nil)
  log("ALIVE ", robot.id, " ", 0.499935)
  log("travels for source (", 1.5, ",", -2, ") : ", 3)
end
function step() end
"""


def test_log_tabs_and_io_write_prefix(tmp_path):
    write(tmp_path, {"x.argos": argos(robots=2), "c.lua": LOGGER})
    r = essaim("run", "x.argos", "--ticks", "1", "--log-prefix", "--out", "o", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    lines = [l for l in r.stdout.splitlines() if l.startswith("[t=")]
    assert lines == ["[t=0 fb0] hello12.51", "[t=0 fb0] written 3", "[t=0 fb0] open line",
                     "[t=0 fb1] hello12.51", "[t=0 fb1] written 3", "[t=0 fb1] open line"], r.stdout


def test_log_and_logerr_concatenate_as_argos_and_print_keeps_tabs(tmp_path):
    loop = 'function init() log("loop ", 2, false) logerr("x", 0.25) print("y", 1) end\n'
    write(tmp_path, {"x.argos": argos(robots=1, loop='<loop_functions script="loop.lua" />'), "c.lua": ARGOS_LOG,
                     "loop.lua": loop})
    r = essaim("run", "x.argos", "--ticks", "1", "-q", "--out", "o", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines() == ["a112.5nil1e+080.30.3333330z", "p\t1\t2.5\ttrue\tnil", "ALIVE fb0 0.499935",
                                     "travels for source (1.5,-2) : 3", "loop 20", "y\t1"], r.stdout
    assert r.stderr.splitlines() == ["e7 0.5", "x0.25"], r.stderr


def test_devices_lists_what_every_controller_has():
    out = essaim("devices").stdout
    for name in ("robot.id", "robot.params", "robot.random", "log(...)"):
        assert name in out, name
    assert out.index("robot.id") < out.index("ACTUATORS")


def test_a_newline_inside_a_log_line_starts_a_line_of_the_same_stream(tmp_path):
    ctrl = 'function init() log("a\\nbc", 1) logerr("e\\nf") print("p\\nq") end\nfunction step() end\n'
    write(tmp_path, {"x.argos": argos(robots=1), "c.lua": ctrl})
    r = essaim("run", "x.argos", "--ticks", "1", "-q", "--log-prefix", "--out", "o", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert r.stdout.splitlines() == ["[t=0 fb0] a", "[t=0 fb0] bc1", "[t=0 fb0] p", "[t=0 fb0] q"], r.stdout
    assert r.stderr.splitlines() == ["[t=0 fb0] e", "[t=0 fb0] f"], r.stderr
