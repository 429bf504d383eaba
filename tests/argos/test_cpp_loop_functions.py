"""C++ loop functions built against essaim's ARGoS API (docs/loop-functions.md, "C++ loop
functions"): a course-style project through pkg-config, every hook and call of the census
through find_package(ARGoS), the clustering loop functions in C++ against their Lua twin,
and the error paths."""
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from argos_projects import ESSAIM, HERE, ROOT, build_project, need_essaim, run, skip_without_python_module

pytestmark = need_essaim


@pytest.fixture(scope="module")
def course(tmp_path_factory):
    return build_project(HERE / "course_project", tmp_path_factory.mktemp("course"))


@pytest.fixture(scope="module")
def census(tmp_path_factory):
    return build_project(HERE / "census_project", tmp_path_factory.mktemp("census"))


def score_rows(folder):
    lines = (folder / "score.txt").read_text().splitlines()
    rows = [line.split("\t") for line in lines if not line.startswith("#")]
    return [(int(t), robot, float(steps), float(ground)) for t, robot, steps, ground in rows], lines[-1]


def test_course_project_runs_unmodified(course, tmp_path):
    done = run(course / "course.argos", "--out", str(tmp_path / "out"), cwd=course)
    assert done.returncode == 0, done.stderr
    assert "warning" not in done.stderr  # every attribute of the file is read
    assert "course: 3 objects placed" in done.stdout and "course: done" in done.stdout
    assert "course: 5 robots" in done.stdout  # two in the file, three added and placed by Init
    rows, last = score_rows(tmp_path / "out" / "files")  # the run's working folder (docs/loop-functions.md)
    assert [t for t, robot, _, _ in rows if robot == "fb0"] == list(range(1, 31))  # the end: tick 30
    added = ["student0", "student1", "student2"]
    assert all([t for t, robot, _, _ in rows if robot == r] == list(range(1, 31)) for r in added)
    assert all(steps == t for t, _, steps, _ in rows)  # the controllers' `steps`, read from their Lua state
    # fb0 starts on white; the floor turns black at tick 10 (SetChanged), and its sensor sees it at once.
    assert [ground for t, robot, _, ground in rows if robot == "fb0"] == [1.0] * 9 + [0.0] * 21
    assert all(ground == 0 for _, robot, _, ground in rows if robot == "fb1")  # in the nest
    words = last.split()
    assert words[:6] == ["#", "finished", "at", "30", "objects", "3"] and int(words[7]) + int(words[9]) == 18
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["status"] == "ok" and summary["finished_by"] == "loop_functions"


def test_course_project_is_reproducible_at_any_thread_count(course, tmp_path):
    outputs = []
    for threads in ("1", "2"):
        done = run(course / "course.argos", "--threads", threads, "--out", str(tmp_path / threads), cwd=course)
        assert done.returncode == 0, done.stderr
        outputs.append((tmp_path / threads / "files" / "score.txt").read_text())
    assert outputs[0] == outputs[1]


def test_label_alone_is_found_in_argos_plugin_path(course, tmp_path):
    argos = tmp_path / "by_label.argos"
    text = (course / "course.argos").read_text().replace('library="build/libcourse_loop_functions" ', "")
    argos.write_text(text.replace('script="course.lua"', f'script="{course / "course.lua"}"'))
    done = run(argos, "--out", str(tmp_path / "a"), cwd=tmp_path, env={"ARGOS_PLUGIN_PATH": str(course / "build")})
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "a" / "files" / "score.txt").exists()  # the run's working folder, not the launch folder
    assert not (tmp_path / "score.txt").exists()
    done = run(argos, "--out", str(tmp_path / "b"), cwd=tmp_path, env={"ARGOS_PLUGIN_PATH": ""})
    assert done.returncode == 2
    assert "no loop functions registered as 'course_loop_functions'" in done.stderr


def test_each_seed_keeps_its_score_file_under_essaim_test(course, tmp_path):
    """Four seeds two at a time: four score.txt, one per run folder, checked by column; the
    project's folder keeps no score file of its own (docs/testing.md, files/PATH[COLUMN])."""
    spec = course / "course_files.test.toml"
    spec.write_text('experiment = "course.argos"\nseeds = 4\nexpect = [\n  "each errors == 0",\n'
                    '  "each files/score.txt[tick].last == 30",\n  "each files/score.txt[steps].max == 30",\n'
                    '  "each files/score.txt[tick].rows == 150",\n]\n')
    (course / "score.txt").unlink(missing_ok=True)
    done = subprocess.run([ESSAIM, "test", str(spec), "-j", "2", "--out", str(tmp_path / "t")], cwd=tmp_path,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "5 of 5 expectations hold" in done.stdout
    scores = [(tmp_path / "t" / f"seed-{seed}" / "files" / "score.txt").read_text() for seed in (1, 2, 3, 4)]
    assert all("# finished at 30 objects 3" in score for score in scores)
    assert not (course / "score.txt").exists()


CENSUS_EXPECTED = {
    "point": "1.5,2.5", "corner": "0.1,0.2,0.3", "flag": "1", "count": "7", "defaulted": "2.5",
    "has_census": "1", "children": "census;second;", "missing_attribute_throws": "1",
    "foot_bots": "2", "boxes": "1", "cylinders": "1", "lights": "1", "fb1_x": "1", "fb1_controller": "student",
    "crate_yaw_degrees": "30", "crate_size_x": "0.2", "crate_movable": "1", "lamp_intensity": "3",
    "arena_x": "4", "unknown_type_throws": "1", "rng_in_range": "1", "cylinders_after_add": "2",
    "lights_after_add": "2", "added_led_green": "1", "boxes_after_remove": "1",
    "foot_bots_after_add": "3", "added_robot_moved": "1", "added_robot_x": "1.5", "added_robot_leds": "13",
    "added_robot_counter": "42", "add_unknown_controller_throws": "1", "add_duplicate_id_throws": "1",
    "add_outside_throws": "1", "add_bad_rab_range_throws": "1",
    "late_robot_ok": "1", "foot_bots_after_late_add": "4",
    "move_onto_robot": "0", "move_check_only": "1", "crate_x_after_check": "-1", "move_free": "1",
    "crate_y_after_move": "1.5", "crate_led_blue": "1", "lamp_intensity_set": "2.5", "quaternion_yaw": "1.5708",
    "seed": "5", "max_clock": "500", "lua_counter": "42", "lua_energy": "7.5", "lua_missing_is_nil": "1",
    "post_experiment": "3", "destroy": "1",
}


def test_every_hook_and_call_of_the_census(census, tmp_path):
    done = run(census / "census.argos", "--out", str(tmp_path / "out"), cwd=census)
    assert done.returncode == 0, done.stderr
    assert "warning" not in done.stderr
    lines = [line.split(" ", 1) for line in (tmp_path / "out" / "files" / "census.txt").read_text().splitlines()]
    seen = dict(lines)
    for key, value in CENSUS_EXPECTED.items():
        assert seen.get(key) == value, key
    assert [v for k, v in lines if k == "post_step"] == ["1", "2", "3"]
    assert "census: an error line" in done.stderr  # LOGERR, through essaim's log


def test_second_generator_draws_its_own_stream(census, tmp_path):
    done = run(census / "census.argos", "--seed", "6", "--out", str(tmp_path / "out"), cwd=census)
    assert done.returncode == 0, done.stderr
    other = dict(line.split(" ", 1) for line in (tmp_path / "out" / "files" / "census.txt").read_text().splitlines())
    assert other["seed"] == "6" and other["rng_first_of_second"] != "0.8973"


def census_variant(census, tmp_path, library, label):
    text = (census / "census.argos").read_text()
    text = text.replace('library="build/libcensus_loop_functions.so"', f'library="{library}"')
    argos = census / f"{tmp_path.name}.argos"
    argos.write_text(text.replace('label="census_loop_functions"', f'label="{label}"'))
    return run(argos, "--out", str(tmp_path / "out"), cwd=census)


def test_exception_from_a_hook_ends_the_run_with_its_message(census, tmp_path):
    done = census_variant(census, tmp_path, "build/libthrowing_loop_functions", "throwing_loop_functions")
    assert done.returncode == 1
    assert "loop functions (PostStep): " in done.stderr
    assert "throwing_loop_functions.cpp:8: the score file is gone at tick 3" in done.stderr
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["status"] == "failed" and summary["ticks"] == 3


@pytest.mark.parametrize("library, label, message", [
    ("build/libnothing", "census_loop_functions", "library 'build/libnothing' not found"),
    ("build/libcensus_loop_functions", "nope", "no loop functions registered as 'nope'"),
    ("build/libold_api_loop_functions", "old_api_loop_functions",
     "built for essaim's ARGoS API version 0, this essaim provides version 4"),
    ("build/liblua51_headers_loop_functions", "lua51_headers_loop_functions",
     "calls lua_objlen, which Lua 5.4 does not have"),
    ("build/liblua51_linked_loop_functions", "lua51_linked_loop_functions",
     "calls Lua (lua_gettop) and is linked against liblua5.1.so.0"),
])
def test_bad_libraries_are_clear_errors(census, tmp_path, library, label, message):
    done = census_variant(census, tmp_path, library, label)
    assert done.returncode == 2, done.stderr
    assert message in done.stderr
    assert "<loop_functions>" in done.stderr  # names the file, line and element


@pytest.fixture(scope="module")
def clustering(tmp_path_factory):
    return build_project(HERE / "clustering_cpp", tmp_path_factory.mktemp("clustering"))


# The C++ port of arenas/clustering.argos's Lua loop functions: the same metrics and series, and
# the same numbers at any thread count. Its CreateRNG("argos") draws ARGoS's numbers (the
# category seeded with the experiment's seed), not the Lua twin's experiment.random, so the
# two place their cylinders apart and their values differ.
@pytest.mark.parametrize("seed", ["1", "7"])
def test_clustering_in_cpp_keeps_the_lua_twins_metrics_at_any_thread_count(clustering, tmp_path, seed):
    outs = {}
    for threads in ("1", "2"):
        out = outs[threads] = tmp_path / f"cpp{threads}"
        done = run(HERE / "clustering_cpp" / "clustering_cpp.argos", "--seed", seed, "--threads", threads, "--out",
                   str(out), "--set",
                   f"loop_functions.library={clustering / 'build' / 'libclustering_loop_functions.so'}", "--set",
                   f"loop_functions.output.dir={out}", cwd=tmp_path)
        assert done.returncode == 0, done.stderr
        assert "warning" not in done.stderr
    lua = tmp_path / "lua"
    done = run(ROOT / "arenas" / "clustering.argos", "--seed", seed, "--out", str(lua), cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    one, two = (json.loads((outs[t] / "cpp_metrics.json").read_text()) for t in ("1", "2"))
    assert one == two
    assert (outs["1"] / "cpp_timeseries.csv").read_text() == (outs["2"] / "cpp_timeseries.csv").read_text()
    # all_delivered_tick is there only when every cylinder arrived, which the two placements
    # (and, since the spring-hold clustering controller, seed 7's Lua run) decide apart.
    optional = {"all_delivered_tick"}
    assert sorted(set(one) - optional) == sorted(set(json.loads((lua / "metrics.json").read_text())) - optional)
    header = (lua / "timeseries.csv").read_text().splitlines()[0]
    assert (outs["1"] / "cpp_timeseries.csv").read_text().splitlines()[0] == header


def test_installed_essaim_builds_and_runs_the_course_project(tmp_path):
    """cmake --install: bin/essaim, lib/ (the API and its aliases, the .pc, the CMake
    package), include/argos3, share/argos3/cmake; the course project builds against it."""
    prefix = tmp_path / "prefix"
    build = Path(ESSAIM).resolve().parent
    done = subprocess.run(["cmake", "--install", str(build), "--prefix", str(prefix)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    course = build_project(HERE / "course_project", tmp_path, prefix=prefix)
    done = subprocess.run([str(prefix / "bin" / "essaim"), "run", "course.argos", "--out", str(tmp_path / "out")],
                          cwd=course, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert "# finished at 30 objects 3" in (tmp_path / "out" / "files" / "score.txt").read_text()


def test_python_module_runs_cpp_loop_functions(course, tmp_path):
    """The Python module loads the same API library: a run, its end and a reset."""
    module = Path(ESSAIM).resolve().parent / "python"
    skip_without_python_module()
    script = (
        "import essaim\n"
        "s = essaim.Simulation('course.argos', seed=3)\n"
        "s.run(); s.finish()\n"
        "first = open('score.txt').read()\n"
        "s.reset(); s.run(); s.finish()\n"
        "assert open('score.txt').read() == first\n"
        "print(first.splitlines()[-1])\n")
    done = subprocess.run([sys.executable, "-c", script], cwd=course, capture_output=True, text=True, timeout=300,
                          env=dict(os.environ, PYTHONPATH=str(module)))
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("# finished at 30 objects 3")


def test_a_file_that_is_no_library_is_a_clear_error(census, tmp_path):
    (census / "build" / "libtext.so").write_text("not a library\n")
    done = census_variant(census, tmp_path, "build/libtext.so", "text")
    assert done.returncode == 2
    assert "build/libtext.so: not a 64-bit ELF shared library" in done.stderr


def test_a_library_linked_to_another_lua_but_not_calling_it_runs(census, tmp_path):
    done = census_variant(census, tmp_path, "build/liblua51_no_calls_loop_functions", "lua51_no_calls_loop_functions")
    assert done.returncode == 0, done.stderr
    needed = subprocess.run(["readelf", "-d", str(census / "build" / "liblua51_no_calls_loop_functions.so")],
                            capture_output=True, text=True).stdout
    assert "liblua5.1.so.0" in needed
