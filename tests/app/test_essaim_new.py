"""`essaim new NAME` (docs/testing.md): the folder runs, its `ctest` passes at once and fails
with the expectation and the seeds named once the controller is broken; luacheck is clean on it."""
import shutil
import subprocess
import xml.etree.ElementTree as ET

import pytest

from clitest import essaim, need_essaim

pytestmark = need_essaim
CTEST = shutil.which("ctest")
LUACHECK = shutil.which("luacheck")


def ctest(folder):
    return subprocess.run([CTEST, "--output-on-failure"], cwd=folder, capture_output=True, text=True, timeout=300)


@pytest.mark.skipif(not CTEST, reason="ctest is not installed")
@pytest.mark.parametrize("template", ["empty", "aggregation"])
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
    suite = ET.parse(folder / "demo.junit.xml").getroot().find("testsuite")
    assert int(suite.get("failures")) >= 1


@pytest.mark.skipif(not LUACHECK, reason="luacheck is not installed (Debian lua-check; scripts/setup.sh)")
def test_luacheck_is_clean_on_a_new_project_and_catches_a_typo(tmp_path):
    for template in ("empty", "aggregation"):
        assert essaim("new", template, "--template", template, cwd=tmp_path).returncode == 0
        r = subprocess.run([LUACHECK, "--no-color", "."], cwd=tmp_path / template, capture_output=True, text=True)
        assert r.returncode == 0, r.stdout
    lua = tmp_path / "empty" / "empty.lua"
    lua.write_text(lua.read_text().replace("robot.proximity[i]", "robot.proximty[i]"))
    r = subprocess.run([LUACHECK, "--no-color", "."], cwd=tmp_path / "empty", capture_output=True, text=True)
    assert r.returncode == 1 and "accessing undefined field 'proximty" in r.stdout


def test_bad_names_and_existing_folders_are_refused(tmp_path):
    (tmp_path / "taken").mkdir()
    r = essaim("new", "taken", cwd=tmp_path)
    assert r.returncode == 2 and "taken already exists; nothing written" in r.stderr
    r = essaim("new", "../up", cwd=tmp_path)
    assert r.returncode == 2 and "a name is a letter" in r.stderr
    r = essaim("new", "x", "--template", "swarming", cwd=tmp_path)
    assert r.returncode == 2 and not (tmp_path / "x").exists()
