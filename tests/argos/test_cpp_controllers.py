"""ARGoS C++ controllers built and run unmodified (docs/cpp-controllers.md): a project laid out
as argos3-examples is (controllers/, loop_functions/, experiments/), built through pkg-config
and find_package; its diffusion, flocking (RAB, camera, positioning, LEDs) and ground forager
against their Lua twins, bit for bit at 1 and 2 threads; Lua and C++ robots in one swarm;
controllers and loop functions reaching each other; and controllers that go wrong."""
import json
from pathlib import Path

import pytest

from argos_projects import HERE, build_project, need_essaim, run

pytestmark = need_essaim


@pytest.fixture(scope="module")
def examples(tmp_path_factory):
    return build_project(HERE / "examples_project", tmp_path_factory.mktemp("examples"))


@pytest.fixture(scope="module")
def faulty(tmp_path_factory):
    return build_project(HERE / "faulty_project", tmp_path_factory.mktemp("faulty"))


def run_ok(project: Path, experiment: str, out: Path, *args):
    done = run(project / experiment, "--out", str(out), *args, cwd=project)
    assert done.returncode == 0, done.stdout + done.stderr
    return done


def poses(out: Path) -> str:
    text = (out / "files" / "poses.txt").read_text()
    assert text, "the loop functions logged no pose"
    return text


@pytest.mark.parametrize("behaviour", ["diffusion", "flocking", "forager"])
def test_cpp_controller_matches_its_lua_twin_bit_for_bit(examples, tmp_path, behaviour):
    runs = {}
    for name, experiment, threads in (("cpp1", f"experiments/{behaviour}.argos", "1"),
                                      ("cpp2", f"experiments/{behaviour}.argos", "2"),
                                      ("lua1", f"experiments/{behaviour}_lua.argos", "1")):
        run_ok(examples, experiment, tmp_path / name, "--threads", threads)
        runs[name] = poses(tmp_path / name)
    assert runs["cpp1"] == runs["cpp2"]  # any thread count
    assert runs["cpp1"] == runs["lua1"]  # exact floats (%a): the same readings, the same commands
    first, last = runs["cpp1"].splitlines()[0].split(), runs["cpp1"].splitlines()[-1].split()
    assert first[0] == "1" and last[0] == "600"
    moved = {line.split()[1] for line in runs["cpp1"].splitlines() if line.split()[0] == "600"}
    assert len(moved) >= 10  # every robot logged to the end


def test_robots_move_and_forage(examples, tmp_path):
    run_ok(examples, "experiments/forager.argos", tmp_path / "out")
    start, end = {}, {}
    for line in poses(tmp_path / "out").splitlines():
        tick, robot, x, y, _ = line.split()
        (start if tick == "1" else end if tick == "600" else {})[robot] = (float.fromhex(x), float.fromhex(y))
    assert sum(abs(end[r][0] - start[r][0]) + abs(end[r][1] - start[r][1]) > 0.3 for r in start) >= 8
    # The controllers report finds to the loop functions' board (found through GetLoopFunctions);
    # the loop functions count them again through each robot's controller (dynamic_cast).
    words = (tmp_path / "out" / "files" / "finds.txt").read_text().split()
    assert words[0] == "reported" and words[2] == "counted" and int(words[1]) == int(words[3]) > 0


def test_lua_and_cpp_robots_in_one_swarm(examples, tmp_path):
    run_ok(examples, "experiments/mixed.argos", tmp_path / "out", "--threads", "2")
    lines = poses(tmp_path / "out").splitlines()
    robots = {line.split()[1] for line in lines}
    assert robots == {f"cpp{i}" for i in range(5)} | {f"lua{i}" for i in range(5)}
    words = (tmp_path / "out" / "files" / "finds.txt").read_text().split()
    assert int(words[1]) == int(words[3])  # only the C++ robots report and are counted
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["status"] == "ok" and summary["robots"] == 10


def test_find_package_builds_the_same_project(tmp_path):
    project = build_project(HERE / "examples_project", tmp_path, cmake_args=["-DUSE_FIND_PACKAGE=ON"])
    run_ok(project, "experiments/diffusion.argos", tmp_path / "out", "--ticks", "50")
    assert poses(tmp_path / "out").splitlines()[-1].split()[0] == "50"


def test_set_reaches_cpp_params(examples, tmp_path):
    run_ok(examples, "experiments/diffusion.argos", tmp_path / "slow", "--ticks", "100")
    run_ok(examples, "experiments/diffusion.argos", tmp_path / "fast", "--ticks", "100",
           "--set", "controllers.diffusion.params.velocity=15")
    assert poses(tmp_path / "slow") != poses(tmp_path / "fast")
    run_ok(examples, "experiments/flocking.argos", tmp_path / "child", "--ticks", "50",
           "--set", "controllers.flocking.params.flocking.velocity=9")


def faulty_run(faulty, tmp_path, controller, *args):
    out = tmp_path / controller
    done = run(faulty / "faulty.argos", "--out", str(out),
               "--set", f"arena.distribute.entity.foot-bot.controller.config={controller}", *args, cwd=faulty)
    summary_file = out / "summary.json"
    return done, json.loads(summary_file.read_text()) if summary_file.exists() else None


def test_an_exception_stops_its_robot_and_the_others_run_on(faulty, tmp_path):
    done, summary = faulty_run(faulty, tmp_path, "thrower")
    assert done.returncode == 0, done.stderr
    assert summary["status"] == "controller_error" and summary["ticks"] == 100
    [error] = summary["controller_errors"]
    assert error["robot"] == "fb2" and error["tick"] == 20
    assert "faulty.cpp:" in error["message"] and "the thrower gives up at tick 20" in error["message"]
    assert "fb2" in done.stderr and "the thrower gives up" in done.stderr


def test_get_sensor_of_an_undeclared_device_is_bad_input(faulty, tmp_path):
    done, _ = faulty_run(faulty, tmp_path, "undeclared")
    assert done.returncode == 2, done.stderr
    assert "footbot_light" in done.stderr and "faulty.argos:14" in done.stderr


def test_a_segfault_leaves_a_summary_naming_the_robot_and_tick(faulty, tmp_path):
    done, summary = faulty_run(faulty, tmp_path, "crasher", "--threads", "2")
    assert done.returncode == 3, done.stderr
    assert summary["status"] == "crashed"
    assert summary["crash"]["robot"] == "fb3" and summary["crash"]["tick"] == 30
    assert summary["crash"]["call"] == "ControlStep" and "SIGSEGV" in summary["crash"]["signal"]
    assert "robot fb3" in done.stderr and "tick 30" in done.stderr


def test_random_draws_and_logs_do_not_depend_on_threads(faulty, tmp_path):
    outputs = []
    for threads in ("1", "2"):
        done, summary = faulty_run(faulty, tmp_path / threads, "walker", "--threads", threads, "--record")
        assert done.returncode == 0, done.stderr
        logged = "".join(line for line in done.stdout.splitlines(True) if not line.startswith("essaim:"))  # no timings
        outputs.append((logged, (tmp_path / threads / "walker" / "recording.bin").read_bytes()))
    assert outputs[0] == outputs[1]
    assert outputs[0][0].count("first draw") == 6 and "turns" in outputs[0][0]


def test_loop_functions_add_robots_that_run_a_cpp_controller(faulty, tmp_path):
    out = tmp_path / "spawned"
    spawner = faulty / "spawner.argos"
    text = (faulty / "faulty.argos").read_text().replace(
        "  <arena", '  <loop_functions library="build/libfaulty" label="spawner"/>\n  <arena')
    spawner.write_text(text.replace('config="thrower"', 'config="walker"'))
    done = run(spawner, "--out", str(out), "--threads", "2", cwd=faulty)
    assert done.returncode == 0, done.stderr
    summary = json.loads((out / "summary.json").read_text())
    assert summary["robots"] == 8 and summary["status"] == "ok"
    # Their Init ran when added (its log line), and the loop functions reach their controllers.
    assert "spawned0 first draw" in done.stdout and "spawned1 first draw" in done.stdout
    assert done.stdout.count(" walks") == 8
