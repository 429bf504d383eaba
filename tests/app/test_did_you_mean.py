"""Misspelled sensors, actuators and --set element ids get the closest name."""
from clitest import ROOT, argos, essaim, need_essaim, write

pytestmark = need_essaim


def test_a_misspelled_sensor_and_actuator(tmp_path):
    text = argos(sensors='<footbot_proximty implementation="default" />').replace(
        '<differential_steering implementation="default" /></actuators>',
        '<differential_steering implementation="default" /><led implementation="default" /></actuators>')
    write(tmp_path, {"x.argos": text, "c.lua": "function init() end\nfunction step() end\n"})
    r = essaim("check", "x.argos", cwd=tmp_path)
    assert r.returncode == 2
    assert "x.argos:9: <footbot_proximty>: unknown sensor; did you mean <footbot_proximity>? (see `essaim devices`)" \
        in r.stderr, r.stderr
    assert "x.argos:8: <led>: unknown actuator; did you mean <leds>?" in r.stderr


def test_a_sensor_among_the_actuators_is_told_where_it_goes(tmp_path):
    text = argos().replace('<differential_steering implementation="default" /></actuators>',
                           '<differential_steering implementation="default" />'
                           '<footbot_proximity implementation="default" /></actuators>')
    write(tmp_path, {"x.argos": text, "c.lua": "function init() end\nfunction step() end\n"})
    r = essaim("check", "x.argos", cwd=tmp_path)
    assert r.returncode == 2
    assert "<footbot_proximity>: 'footbot_proximity' is a sensor, not an actuator: it goes inside <sensors>" \
        in r.stderr, r.stderr


def test_a_set_path_with_a_wrong_id_names_the_closest(tmp_path):
    r = essaim("check", ROOT / "arenas/foraging.argos", "--set", "controllers.foragin.params.EPSILONGREED=0.3")
    assert r.returncode == 2
    assert "no element at 'controllers.foragin'; did you mean 'foraging'?" in r.stderr, r.stderr
    r = essaim("check", ROOT / "arenas/foraging.argos", "--set", "arean.distribute.entity.quantity=3")
    assert "no element at 'arean'; did you mean 'arena'?" in r.stderr, r.stderr
