"""Lua loop functions at ARGoS's points of start-up and shut-down (docs/loop-functions.md,
"Hooks"): floor_color is sampled after init(), so a zone init() reads shows from tick 1, and
again after experiment.floor_changed(); destroy() runs once at the end, while the robots'
states can still be read, and its log lines are kept."""
from clitest import argos, need_essaim, run, write

pytestmark = need_essaim

GROUND = '<footbot_motor_ground implementation="rot_z_only" />'

CONTROLLER = """
steps = 0
function step()
  steps = steps + 1
  log("ground " .. robot.motor_ground[1].value)
end
"""

LOOP = """
local zone_x, radius = 100, 0     -- outside the arena until init() reads the zone
function init()
  zone_x = tonumber(experiment.params.zone.x)
  radius = tonumber(experiment.params.zone.radius)
end
function floor_color(x, y)
  if (x - zone_x) ^ 2 + y ^ 2 < radius ^ 2 then return "black" end
  return "white"
end
function post_step()
  if experiment.tick == 2 then radius = 10; experiment.floor_changed() end
end
function destroy()
  log("destroy: fb2 steps " .. experiment.robots[3]:lua_global("steps"))
end
"""


def experiment():
    loop = '<loop_functions script="loop.lua"><zone x="-1" radius="0.3"/></loop_functions>'
    text = argos(robots=3, length=4, sensors=GROUND, loop=loop)
    return text.replace('<arena size="4, 4, 1" center="0, 0, 0.5">',
                        '<arena size="4, 4, 1" center="0, 0, 0.5">\n'
                        '    <floor id="f" source="loop_functions" pixels_per_meter="50"/>')


def grounds(stdout):
    """{(tick, robot): ground} from --log-prefix lines "[t=T fbN] ground G"."""
    out = {}
    for line in stdout.splitlines():
        if "] ground " in line:
            head, value = line.split("] ground ")
            tick, robot = head.lstrip("[t=").split()
            out[(int(tick), robot)] = float(value)
    return out


def test_floor_follows_init_and_floor_changed(tmp_path):
    write(tmp_path, {"x.argos": experiment(), "c.lua": CONTROLLER, "loop.lua": LOOP})
    r, summary = run(tmp_path, "x.argos", "--log-prefix")
    assert r.returncode == 0, r.stderr
    g = grounds(r.stdout)
    # fb0 stands at x = -1, inside the zone init() read; fb1 (x = -0.5) and fb2 (x = 0) outside.
    assert [g[(t, "fb0")] for t in (1, 2, 3, 4)] == [0.0] * 4, g
    # floor_changed() in post_step at tick 2: every robot is on black from tick 3.
    assert [g[(t, "fb2")] for t in (1, 2, 3, 4)] == [1.0, 1.0, 0.0, 0.0], g


def test_destroy_runs_once_at_the_end_with_the_robots_states(tmp_path):
    write(tmp_path, {"x.argos": experiment(), "c.lua": CONTROLLER, "loop.lua": LOOP})
    r, summary = run(tmp_path, "x.argos")
    assert r.returncode == 0, r.stderr
    assert r.stdout.count("destroy: fb2 steps 4") == 1, r.stdout
    assert summary["status"] == "ok"


def test_an_error_in_destroy_fails_the_run(tmp_path):
    loop = LOOP.replace('log("destroy: fb2 steps "', 'error("no shutdown"); log(""')
    write(tmp_path, {"x.argos": experiment(), "c.lua": CONTROLLER, "loop.lua": loop})
    r, summary = run(tmp_path, "x.argos")
    assert r.returncode == 1, r.stderr
    assert "loop functions (destroy)" in r.stderr and "no shutdown" in r.stderr, r.stderr
    assert summary["status"] == "failed"
