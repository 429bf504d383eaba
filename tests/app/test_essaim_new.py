"""`essaim new NAME` (docs/testing.md): the folder runs, its `ctest` passes at once and fails
with the expectation and the seeds named once the controller is broken; luacheck is clean on it."""
import json
import os
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from clitest import ESSAIM, check_junit_shape, essaim, need_essaim

pytestmark = need_essaim
CTEST = shutil.which("ctest")
LUACHECK = shutil.which("luacheck")


def ctest(folder):
    return subprocess.run([CTEST, "--output-on-failure"], cwd=folder, capture_output=True, text=True, timeout=300)


@pytest.mark.skipif(not CTEST, reason="ctest is not installed")
@pytest.mark.parametrize("template", ["empty", "aggregation", "foraging"])
def test_a_new_project_runs_passes_and_fails_when_broken(tmp_path, template):
    r = essaim("new", "demo", "--template", template, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    folder = tmp_path / "demo"
    assert {p.name for p in folder.iterdir()} >= {"demo.argos", "demo.lua", "demo_loop.lua", "demo.test.toml",
                                                  "CMakeLists.txt", "CTestTestfile.cmake", ".luarc.json",
                                                  ".luacheckrc", "README.md", "types"}
    controller = (folder / "demo.lua").read_text()
    for hook in ("function init()", "function step()", "function reset()", "function destroy()"):
        assert hook in controller
    assert essaim("run", "demo.argos", "-q", cwd=folder).returncode == 0
    passed = ctest(folder)
    assert passed.returncode == 0, passed.stdout
    suite = ET.parse(folder / "demo.junit.xml").getroot().find("testsuite")
    assert suite.get("failures") == "0" and int(suite.get("tests")) >= 3

    (folder / "demo.lua").write_text(controller.replace("robot.wheels.set_velocity", "robot.wheel.set_velocity"))
    failed = ctest(folder)
    assert failed.returncode != 0
    assert "each errors == 0" in failed.stdout and "FAIL     1, 2, 3, 4, 5, 6, 7, 8, 9, 10" in failed.stdout
    assert "attempt to index a nil value (field 'wheel')" in failed.stdout
    root = ET.parse(folder / "demo.junit.xml").getroot()
    check_junit_shape(root)
    assert int(root.find("testsuite").get("failures")) >= 1


@pytest.mark.skipif(not LUACHECK, reason="luacheck is not installed (Debian lua-check; scripts/setup.sh)")
def test_luacheck_is_clean_on_a_new_project_and_catches_a_typo(tmp_path):
    for template in ("empty", "aggregation", "foraging"):
        assert essaim("new", template, "--template", template, cwd=tmp_path).returncode == 0
        r = subprocess.run([LUACHECK, "--no-color", "."], cwd=tmp_path / template, capture_output=True, text=True)
        assert r.returncode == 0, r.stdout
    lua = tmp_path / "empty" / "empty.lua"
    lua.write_text(lua.read_text().replace("robot.proximity[i]", "robot.proximty[i]"))
    r = subprocess.run([LUACHECK, "--no-color", "."], cwd=tmp_path / "empty", capture_output=True, text=True)
    assert r.returncode == 1 and "accessing undefined field 'proximty" in r.stdout


@pytest.mark.skipif(not CTEST, reason="ctest is not installed")
def test_the_cmake_module_declares_the_spec_as_a_ctest(tmp_path):
    """find_package(essaim) from the build folder: essaim_add_test with the spec's timeout and labels."""
    assert essaim("new", "demo", cwd=tmp_path).returncode == 0
    folder = tmp_path / "demo"
    spec = folder / "demo.test.toml"
    spec.write_text(spec.read_text().replace("timeout = 300", "timeout = 77").replace('["behaviour"]', '["a", "b"]'))
    r = subprocess.run(["cmake", "-S", ".", "-B", "build"], cwd=folder, capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stdout + r.stderr
    listed = json.loads(subprocess.run([CTEST, "--test-dir", "build", "--show-only=json-v1"], cwd=folder,
                                       capture_output=True, text=True, timeout=60).stdout)
    [test] = listed["tests"]
    props = {p["name"]: p["value"] for p in test["properties"]}
    assert test["name"] == "demo_behaviour" and props["TIMEOUT"] == 77 and sorted(props["LABELS"]) == ["a", "b", "essaim"]
    r = subprocess.run([CTEST, "--test-dir", "build"], cwd=folder, capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout
    assert (folder / "build" / "essaim-test" / "demo_behaviour.junit.xml").exists()


def test_bad_names_and_existing_folders_are_refused(tmp_path):
    (tmp_path / "taken").mkdir()
    r = essaim("new", "taken", cwd=tmp_path)
    assert r.returncode == 2 and "taken already exists; nothing written" in r.stderr
    r = essaim("new", "../up", cwd=tmp_path)
    assert r.returncode == 2 and "a name is a letter" in r.stderr
    r = essaim("new", "x", "--template", "swarming", cwd=tmp_path)
    assert r.returncode == 2 and not (tmp_path / "x").exists()


CPP_FILES = ["CMakeLists.txt", "CTestTestfile.cmake", "README.md", "controllers/CMakeLists.txt",
             "controllers/my-swarm/CMakeLists.txt", "controllers/my-swarm/my-swarm.cpp",
             "controllers/my-swarm/my-swarm.h", "experiments/my-swarm.argos", "loop_functions/CMakeLists.txt",
             "loop_functions/my-swarm_loop_functions/CMakeLists.txt",
             "loop_functions/my-swarm_loop_functions/my-swarm_loop_functions.cpp",
             "loop_functions/my-swarm_loop_functions/my-swarm_loop_functions.h", "my-swarm.test.toml"]


@pytest.mark.skipif(not CTEST or not shutil.which("cmake") or not shutil.which("pkg-config"),
                    reason="ctest, cmake and pkg-config are needed to build a C++ project")
def test_the_cpp_template_builds_and_passes_its_test_from_a_fresh_folder(tmp_path):
    """`--template cpp`: argos3-examples' layout, found through pkg-config in the essaim that made it
    (no variable set); a plain `ctest` configures, builds and tests; the build folder's ctest
    rebuilds first, so a broken controller fails it, naming the robots' error."""
    r = essaim("new", "my-swarm", "--template", "cpp", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert "cd my-swarm && ctest" in r.stdout and "essaim run experiments/my-swarm.argos" in r.stdout
    folder = tmp_path / "my-swarm"
    made = sorted(str(p.relative_to(folder)) for p in folder.rglob("*") if p.is_file())
    assert made == sorted(CPP_FILES + [".gitignore"])
    controller = (folder / "controllers/my-swarm/my-swarm.cpp").read_text()
    assert "REGISTER_CONTROLLER(CMySwarm, \"my-swarm_controller\")" in controller
    env = {k: v for k, v in os.environ.items() if k not in ("PKG_CONFIG_PATH", "CMAKE_PREFIX_PATH")}

    passed = subprocess.run([CTEST, "--output-on-failure"], cwd=folder, capture_output=True, text=True,
                            timeout=600, env=env)
    assert passed.returncode == 0, passed.stdout + passed.stderr
    assert "my-swarm_configure" in passed.stdout and "my-swarm_build" in passed.stdout
    suite = ET.parse(folder / "my-swarm.junit.xml").getroot().find("testsuite")
    assert suite.get("failures") == "0" and int(suite.get("tests")) >= 3

    run = essaim("run", "experiments/my-swarm.argos", "-q", "--ticks", "100", cwd=folder)
    assert run.returncode == 0, run.stderr
    rows = (folder / "runs/my-swarm-1/files/spread.csv").read_text().splitlines()
    assert rows[0] == "tick,spread,shrink" and [r.split(",")[0] for r in rows[1:]] == ["0", "50", "100"]
    summary = json.loads((folder / "runs/my-swarm-1/summary.json").read_text())
    assert summary["status"] == "ok" and summary["robots"] == 10 and summary["unread_params"] == []

    source = folder / "controllers/my-swarm/my-swarm.cpp"
    source.write_text(controller.replace("void CMySwarm::ControlStep() {",
                                         "void CMySwarm::ControlStep() {\n  THROW_ARGOSEXCEPTION(\"no step\");"))
    failed = subprocess.run([CTEST, "--test-dir", "build", "--output-on-failure"], cwd=folder, capture_output=True,
                            text=True, timeout=600, env=env)
    assert failed.returncode != 0
    assert "each errors == 0" in failed.stdout and "FAIL     1, 2, 3, 4, 5, 6, 7, 8, 9, 10" in failed.stdout
    assert "my-swarm.cpp:" in failed.stdout and "no step" in failed.stdout


def test_new_help_lists_the_cpp_template(tmp_path):
    r = essaim("new", "--help", cwd=tmp_path)
    assert r.returncode == 0 and "cpp" in r.stdout and "essaim new swarm --template cpp" in r.stdout


def test_the_cpp_template_refuses_a_name_cmake_reserves(tmp_path):
    r = essaim("new", "test", "--template", "cpp", cwd=tmp_path)
    assert r.returncode == 2 and "CMake reserves" in r.stderr and not (tmp_path / "test").exists()


@pytest.mark.skipif(not CTEST or not shutil.which("cmake") or not shutil.which("pkg-config"),
                    reason="ctest, cmake and pkg-config are needed to build a C++ project")
def test_an_installed_essaim_makes_a_cpp_project_that_builds_against_it(tmp_path):
    """From PREFIX/bin/essaim: the project finds PREFIX/lib/pkgconfig and PREFIX/lib/cmake/essaim."""
    prefix = tmp_path / "prefix"
    build = Path(ESSAIM).resolve().parent
    done = subprocess.run(["cmake", "--install", str(build), "--prefix", str(prefix)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    r = subprocess.run([str(prefix / "bin" / "essaim"), "new", "demo", "--template", "cpp"], cwd=tmp_path,
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    top = (tmp_path / "demo" / "CMakeLists.txt").read_text()
    assert f'set(ARGOS_PREFIX "{prefix}"' in top and f'HINTS "{prefix / "lib/cmake/essaim"}"' in top
    env = {k: v for k, v in os.environ.items() if k not in ("PKG_CONFIG_PATH", "CMAKE_PREFIX_PATH")}
    passed = subprocess.run([CTEST, "--output-on-failure"], cwd=tmp_path / "demo", capture_output=True, text=True,
                            timeout=600, env=env)
    assert passed.returncode == 0, passed.stdout + passed.stderr
