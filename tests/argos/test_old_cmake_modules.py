"""The CMake modules older ARGoS releases installed in share/argos3/cmake, which many
projects still call (issue 46, item 5): with CMAKE_MODULE_PATH pointed there, ARGoSCheckQTOpenGL
and FindARGoSQTOpenGL say there are no Qt user functions, and FindLua52/FindLua53 give the
Lua 5.4 essaim runs, so loop functions that read a controller's Lua state build and run; a C++
controller built by the same old-style CMakeLists runs beside a Lua robot."""
import os
import shutil
import subprocess

from argos_projects import HERE, build_project, need_essaim, run, sdk

pytestmark = need_essaim


def test_a_project_using_the_old_modules_builds_and_reads_lua_state(tmp_path):
    project = build_project(HERE / "old_modules_project", tmp_path)
    done = run(project / "old_modules.argos", "--out", str(tmp_path / "out"), cwd=project)
    assert done.returncode == 0, done.stderr
    assert "old modules: fb0 steps 7" in done.stdout, done.stdout


def test_a_controller_built_with_the_old_modules_runs_beside_a_lua_robot(tmp_path):
    project = build_project(HERE / "old_modules_project", tmp_path)
    done = run(project / "old_modules_cpp.argos", "--out", str(tmp_path / "out"), cwd=project)
    assert done.returncode == 0, done.stderr
    assert "old modules: fb0 steps 7" in done.stdout, done.stdout  # the loop functions read the Lua robot
    assert "old modules controller: fb1 steps 7" in done.stdout, done.stdout  # the C++ one said so itself


def test_the_lua_finders_say_which_lua_they_give(tmp_path):
    copy = tmp_path / "p"
    shutil.copytree(HERE / "old_modules_project", copy)
    env = dict(os.environ, PKG_CONFIG_PATH=str(sdk() / "lib" / "pkgconfig"))
    done = subprocess.run(["cmake", "-S", ".", "-B", "build"], cwd=copy, env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "essaim: find_package(Lua52) gives Lua 5.4" in done.stdout, done.stdout
    assert "essaim: find_package(Lua53) gives Lua 5.4" in done.stdout, done.stdout
    assert "no Qt/OpenGL user functions" in done.stdout
