"""A misspelled robot.* or experiment.* field is named with the closest real one (the error
handler reads Lua's own message, so a controller that makes no mistake pays nothing), a
device the controller does not declare says so, and a controller that tests a device for nil
on purpose runs as in ARGoS."""
import json

import pytest

from clitest import essaim, need_essaim, write

pytestmark = need_essaim

EXPERIMENT = """<?xml version="1.0" ?>
<argos-configuration>
  <framework><experiment length="2" ticks_per_second="10" random_seed="1" /></framework>
  <controllers>
    <lua_controller id="c">
      <actuators>
        <differential_steering implementation="default" />
        <leds implementation="default" medium="leds" />
        <range_and_bearing implementation="default" />
      </actuators>
      <sensors>
        <footbot_proximity implementation="default" show_rays="false" />
        <range_and_bearing implementation="medium" medium="rab" show_rays="false" />
      </sensors>
      <params script="c.lua" />
    </lua_controller>
  </controllers>
  LOOP
  <arena size="4, 4, 1" center="0, 0, 0.5">
    <foot-bot id="fb0"><body position="0,0,0" orientation="0,0,0" /><controller config="c" /></foot-bot>
  </arena>
  <physics_engines><dynamics2d id="dyn2d" /></physics_engines>
  <media><range_and_bearing id="rab" /><led id="leds" /></media>
</argos-configuration>
"""


def failure(tmp_path, step, loop=None):
    """The controller error (or loop functions' failure) of a run whose step() is `step`."""
    files = {"c.lua": f"function step()\n  {step}\nend\n",
             "x.argos": EXPERIMENT.replace("LOOP", '<loop_functions script="loop.lua"/>' if loop else "")}
    if loop:
        files["loop.lua"] = loop
    write(tmp_path, files)
    r = essaim("run", "x.argos", "-q", "--out", "out", cwd=tmp_path)
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    errors = summary["controller_errors"]
    return (errors[0]["message"] if errors else summary.get("failure", "")), r


@pytest.mark.parametrize("step, hint", [
    ("robot.wheels.set_velocty(1, 1)", "did you mean robot.wheels.set_velocity?"),
    ("robot.wheel.set_velocity(1, 1)", "did you mean robot.wheels?"),
    ('robot.leds.set_all_colours("red")', "did you mean robot.leds.set_all_colors?"),
    ("local x = robot.proximty[1].value", "did you mean robot.proximity?"),
    ("robot.range_and_bearing.set_dat(1, 5)", "did you mean robot.range_and_bearing.set_data?"),
    ("robot.gripper.lock_positive()",
     "robot.gripper is nil: this controller declares no <footbot_gripper> in its <actuators>"),
])
def test_a_misspelled_field_is_named_with_a_suggestion(tmp_path, step, hint):
    message, r = failure(tmp_path, step)
    assert "c.lua:2: attempt to" in message and hint in message, message
    assert hint in r.stderr, r.stderr


def test_a_nil_the_script_made_itself_gets_no_suggestion(tmp_path):
    message, _ = failure(tmp_path, "local t = {wheels = {}}\n  t.wheels.set_velocity(1, 1)")
    assert "field 'set_velocity'" in message and "did you mean" not in message, message


def test_testing_a_device_for_nil_runs_as_in_argos(tmp_path):
    message, r = failure(tmp_path, 'if robot.gripper == nil and not robot.camera then log("no gripper") end')
    assert message == "" and r.returncode == 0, r.stderr


def test_loop_functions_get_suggestions_for_experiment(tmp_path):
    loop = "function post_step()\n  local n = #experiment.robot\nend\n"
    message, r = failure(tmp_path, "", loop=loop)
    assert "loop.lua:2:" in message and "did you mean experiment.robots?" in message, message
