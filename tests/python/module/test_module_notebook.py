"""The module as a notebook uses it: controller errors and log() lines through `logging`
and `Simulation.errors`, strict, summary before finish, reset, a robot's Lua global,
render() to PNG, yaw in (-pi, pi], recording.bin read back as numpy/pandas, and foot-bots the
loop functions add during the run (listed, logged, recorded absent before their arrival)."""
import json
import logging
import math
import subprocess

import numpy as np
import pytest

from module_paths import FORAGING, SMALL

essaim = pytest.importorskip("essaim")

PNG = b"\x89PNG\r\n\x1a\n"


def controller(tmp_path, body):
    """The foraging arena with a controller of our own (5 robots)."""
    script = tmp_path / "ctrl.lua"
    script.write_text(body)
    return dict(SMALL, **{"controllers.foraging.params.script": str(script)})


NOISY = """
count = 0
function init() log("hello ", 1, true, 1/3, " ", robot.id) end
function step()
  count = count + 1
  info = {n = count, list = {1, 2, 3}, name = robot.id}
  if robot.id == "fb2" and count == 3 then error("boom") end
  if count == 2 then logerr("careful") end
end
function reset() end
function destroy() end
"""


def test_errors_and_log_lines_reach_logging_and_errors(tmp_path, caplog):
    over = controller(tmp_path, NOISY)
    with caplog.at_level(logging.INFO, logger="essaim"):
        with essaim.Simulation(FORAGING, seed=1, overrides=over) as sim:
            infos = [r for r in caplog.records if r.levelno == logging.INFO]
            assert len(infos) == 5 and all("hello" in r.getMessage() for r in infos)
            # ARGoS's log() text: no separator, numbers as C++ streams write them, true as 1
            assert infos[0].getMessage() == "fb0: hello 110.333333 fb0" and infos[0].robot == "fb0"
            assert infos[0].tick == 0
            sim.step(5)
            assert sim.tick == 5  # the error did not stop the run
    warns = [r for r in caplog.records if r.levelno == logging.WARNING]
    assert len(warns) == 5 and {r.tick for r in warns} == {2}
    assert "careful" in warns[0].getMessage()
    errors = [r for r in caplog.records if r.levelno == logging.ERROR]
    assert len(errors) == 1 and "boom" in errors[0].getMessage()
    assert len(sim.errors) == 1
    e = sim.errors[0]
    assert e["robot"] == "fb2" and e["tick"] == 3 and "ctrl.lua:7" in e["message"]


def test_strict_raises_at_the_first_controller_error(tmp_path):
    over = controller(tmp_path, NOISY)
    with essaim.Simulation(FORAGING, seed=1, overrides=over, strict=True) as sim:
        with pytest.raises(essaim.Error, match="boom"):
            sim.step(10)
        assert sim.tick == 3 and len(sim.errors) == 1


def test_summary_before_finish_is_the_run_so_far(tmp_path):
    over = controller(tmp_path, NOISY)
    with essaim.Simulation(FORAGING, seed=1, overrides=over) as sim:
        sim.step(4)
        s = sim.summary
        assert s["status"] == "running" and s["ticks"] == 4 and s["robots"] == 5
        assert len(s["controller_errors"]) == 1
        sim.finish()
        assert sim.summary["status"] == "controller_error"


def test_lua_globals_come_back_as_python_data(tmp_path):
    over = controller(tmp_path, NOISY)
    with essaim.Simulation(FORAGING, seed=1, overrides=over) as sim:
        sim.step(2)
        assert sim.lua_global("fb1", "count") == 2
        assert sim.lua_global(1, "info") == {"n": 2, "list": [1, 2, 3], "name": "fb1"}
        assert sim.lua_global("fb1", "nothing_here") is None
        with pytest.raises(KeyError, match="fb99"):
            sim.lua_global("fb99", "count")
        with pytest.raises(IndexError):
            sim.lua_global(5, "count")


def test_reset_starts_again_with_another_seed():
    with essaim.Simulation(FORAGING, seed=1, overrides=SMALL) as sim:
        sim.step(30)
        first = sim.poses()
        sim.reset(seed=2)
        assert sim.tick == 0 and sim.errors == []
        sim.step(30)
        other = sim.poses()
        sim.reset(seed=1)
        sim.step(30)
        assert np.array_equal(sim.poses(), first) and not np.array_equal(other, first)
        assert sim.summary["seed"] == 1


def test_yaw_is_wrapped():
    with essaim.Simulation(FORAGING, seed=1, overrides=SMALL) as sim:
        for _ in range(10):
            sim.step(50)
            yaw = sim.poses()[:, 2]
            assert np.all(yaw > -math.pi) and np.all(yaw <= math.pi)


def test_render_gives_png_bytes_or_a_file(tmp_path):
    with essaim.Simulation(FORAGING, seed=1, overrides=SMALL) as sim:
        sim.step(10)
        png = sim.render(size=300)
        assert png[:8] == PNG and len(png) > 2000
        assert sim.render(str(tmp_path / "f.png"), size=300) is None
        assert (tmp_path / "f.png").read_bytes()[:8] == PNG
        assert sim._repr_png_()[:8] == PNG  # Jupyter shows the Simulation as its picture
        with pytest.raises(essaim.Error, match="size"):
            sim.render(size=3)


def test_recording_reader_matches_the_recorded_run(essaim_bin, tmp_path):
    out = tmp_path / "run"
    subprocess.run([essaim_bin, "run", FORAGING, "--seed", "3", "--ticks", "40", "--quiet",
                    "--record", "--set", "arena.distribute.entity.quantity=5", "--out", str(out)],
                   check=True)
    rec = essaim.read_recording(str(out))
    assert rec.robot_ids == [f"fb{i}" for i in range(5)] and rec.seed == 3
    assert rec.ticks.tolist() == list(range(41))
    assert rec.poses.shape == (41, 5, 3) and rec.alive.shape == rec.battery.shape == (41, 5)
    assert np.all(rec.poses[:, :, 2] > -math.pi) and np.all(rec.poses[:, :, 2] <= math.pi)
    assert rec.alive.all()
    with essaim.Simulation(FORAGING, seed=3, overrides=SMALL) as sim:
        sim.step(40)
        live, battery = sim.poses(), sim.battery()
    assert rec.battery[-1] == pytest.approx(battery, abs=0.5 / 255)
    assert rec.battery[0] == pytest.approx(np.ones(5))
    assert np.allclose(rec.poses[-1, :, :2], live[:, :2], atol=0.002)  # 1 mm quantisation
    dyaw = np.angle(np.exp(1j * (rec.poses[-1, :, 2] - live[:, 2])))
    assert np.all(np.abs(dyaw) < 0.001)
    df = rec.to_pandas()
    assert list(df.columns) == ["tick", "robot", "x", "y", "yaw", "alive", "battery"]
    assert len(df) == 41 * 5
    last = df[df.tick == 40].set_index("robot")
    assert last.loc["fb3", "x"] == rec.poses[-1, 3, 0]
    with pytest.raises(essaim.Error):
        essaim.read_recording(str(tmp_path / "nope.bin"))


JOINING_ARGOS = """<?xml version="1.0" ?>
<argos-configuration>
  <framework><experiment length="0" ticks_per_second="10" random_seed="3"/></framework>
  <controllers>
    <lua_controller id="walker">
      <actuators><differential_steering implementation="default"/></actuators>
      <sensors><positioning implementation="default"/></sensors>
      <params script="walker.lua"/>
    </lua_controller>
  </controllers>
  <loop_functions script="loop.lua"/>
  <arena size="4,4,1" center="0,0,0.5">
    <foot-bot id="fb0"><body position="0,0,0" orientation="0,0,0"/><controller config="walker"/></foot-bot>
  </arena>
  <physics_engines><dynamics2d id="dyn2d"/></physics_engines>
  <media/>
</argos-configuration>
"""

JOINING_LOOP = """
function init()
  experiment.add_entity("foot-bot", {id = "early", controller = "walker", position = {1, 0}, orientation = 90})
end
function post_step()
  if experiment.tick == 10 then
    experiment.add_entity("foot-bot", {id = "late", controller = "walker", position = {-1, 0}})
  end
end
"""


def test_robots_added_during_the_run(essaim_bin, tmp_path, caplog):
    # The loop functions add one foot-bot in init() and one at tick 10; each logs in init().
    (tmp_path / "walker.lua").write_text('function init() n = 0 log("joined") end\n'
                                         "function step() n = n + 1 robot.wheels.set_velocity(5, 5) end\n")
    (tmp_path / "loop.lua").write_text(JOINING_LOOP)
    argos = tmp_path / "joining.argos"
    argos.write_text(JOINING_ARGOS)
    with caplog.at_level(logging.INFO, logger="essaim"):
        with essaim.Simulation(str(argos)) as sim:
            assert sim.robot_ids == ["fb0", "early"]
            sim.step(20)
            assert sim.robot_ids == ["fb0", "early", "late"]
            assert sim.battery().shape == sim.alive().shape == (3,) and sim.poses().shape == (3, 3)
            assert sim.lua_global("late", "n") == 10 and sim.lua_global(2, "n") == 10
    assert [(r.robot, r.tick) for r in caplog.records if r.getMessage().endswith("joined")] == \
        [("fb0", 0), ("early", 0), ("late", 10)]

    out = tmp_path / "run"
    subprocess.run([essaim_bin, "run", str(argos), "--ticks", "20", "--quiet", "--record", "--out", str(out)],
                   check=True)
    rec = essaim.read_recording(str(out))
    assert rec.robot_ids == ["fb0", "early", "late"]
    assert rec.present[:, :2].all() and not rec.present[:10, 2].any() and rec.present[10:, 2].all()
    assert np.isnan(rec.poses[:10, 2]).all() and np.isnan(rec.battery[:10, 2]).all()
    assert not rec.alive[:10, 2].any() and rec.alive[10:].all()
    assert rec.poses[10, 2, 0] == pytest.approx(-1, abs=0.001)  # where it was added
    df = rec.to_pandas()
    assert len(df) == 21 * 3 - 10 and list(df.index) == list(range(len(df)))
    assert not df.isna().any().any()
    assert df[df.robot == "late"].tick.tolist() == list(range(10, 21))


def test_per_robot_arrays_hold_each_robots_own_value(tmp_path):
    # Each robot's battery as its own sensor reads it (fb1 is refilled in the nest), and
    # alive() as the loop functions' deaths.
    over = controller(tmp_path, "function init() end\n"
                      "function step() b = robot.battery.available_charge end\n")
    with essaim.Simulation(FORAGING, seed=3, overrides=over) as sim:
        sim.step(20)
        assert sim.battery().tolist() == [sim.lua_global(i, "b") for i in range(5)]
        assert len(set(sim.battery().tolist())) == 2
    # Robots that stand still: those outside the nest run out of battery, the others live.
    idle = controller(tmp_path, "function init() end\nfunction step() end\n")
    with essaim.Simulation(FORAGING, seed=3, overrides=idle) as sim:
        sim.run()
        metrics = sim.finish()
        dead = {d["robot"] for d in metrics["dead_robots"]}
        assert 0 < len(dead) < 5
        assert [not a for a in sim.alive()] == [r in dead for r in sim.robot_ids]
