"""Editor support made from the device table (docs/testing.md): `essaim devices --lua-defs`
(Lua language server annotations) covers every device row, loads as Lua, and `--luacheck`
passes every shipped controller and loop-function script."""
import json
import re
import shutil
import subprocess

import pytest

from clitest import ROOT, essaim, need_essaim

pytestmark = need_essaim
LUACHECK = shutil.which("luacheck")
LUA = shutil.which("lua5.4")


def device_rows():
    """(xml element, sensor?, lua key) of every row `essaim devices` prints."""
    rows, sensors = [], False
    for line in essaim("devices").stdout.splitlines():
        sensors = sensors or line.startswith("SENSORS")
        m = re.match(r"\s+<(\S+) implementation=.*->\s+robot\.(\w+)", line)
        if m:
            rows.append((m.group(1), sensors, m.group(2)))
    return rows


def test_every_device_row_has_an_annotation():
    defs = essaim("devices", "--lua-defs").stdout
    rows = device_rows()
    assert len(rows) >= 17
    device_classes = re.findall(r"^---@class essaim\.\w+(?:Actuator|Sensor)$", defs, re.M)
    assert len(device_classes) == len(rows), device_classes
    robot = defs.split("---@class essaim.Robot\n")[1].split("\n\n")[0]
    for xml, _, key in rows:
        assert re.search(rf"^---@field {key} essaim\.robot\.{key} ", robot, re.M), (xml, key)
        assert re.search(rf"^---@class essaim\.robot\.{key}: ", defs, re.M), key
    for name in ("id", "params", "random"):
        assert f"---@field {name} " in robot
    for fn in ("function log(...) end", "function logerr(...) end", "experiment = {}", "robot = {}"):
        assert fn in defs


@pytest.mark.skipif(not LUA, reason="lua5.4 is not installed")
def test_the_annotations_load_as_lua(tmp_path):
    (tmp_path / "essaim.lua").write_text(essaim("devices", "--lua-defs").stdout)
    r = subprocess.run([LUA, "-e", "assert(loadfile('essaim.lua'))"], cwd=tmp_path,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


@pytest.mark.skipif(not LUACHECK, reason="luacheck is not installed (Debian lua-check; scripts/setup.sh)")
def test_luacheck_passes_every_shipped_script(tmp_path):
    config = tmp_path / "luacheckrc"
    config.write_text(essaim("devices", "--luacheck").stdout)
    scripts = sorted(str(p.relative_to(ROOT)) for p in
                     list(ROOT.glob("controllers/**/*.lua")) + list(ROOT.glob("arenas/*.lua")) +
                     list(ROOT.glob("bench/**/*.lua")) + list(ROOT.glob("tests/experiments/*.lua")))
    assert "controllers/foraging.lua" in scripts and "arenas/foraging_loop.lua" in scripts
    r = subprocess.run([LUACHECK, "--no-color", "--config", str(config), *scripts], cwd=ROOT,
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout


@pytest.mark.skipif(not LUACHECK, reason="luacheck is not installed (Debian lua-check; scripts/setup.sh)")
def test_the_docs_recipe_lints_clean_with_the_definitions_beside(tmp_path):
    """docs/testing.md's two commands in a project folder, then `luacheck .`: the definitions
    file is declarations, not a script, and is skipped."""
    (tmp_path / "essaim.d.lua").write_text(essaim("devices", "--lua-defs").stdout)
    (tmp_path / ".luacheckrc").write_text(essaim("devices", "--luacheck").stdout)
    (tmp_path / "c.lua").write_text("function step() robot.wheels.set_velocity(1, 1) end\n")
    r = subprocess.run([LUACHECK, "--no-color", "."], cwd=tmp_path, capture_output=True, text=True)
    assert r.returncode == 0 and "0 warnings" in r.stdout, r.stdout


def test_luarc_and_luacheckrc_declare_the_same_hooks(tmp_path):
    assert essaim("new", "demo", cwd=tmp_path).returncode == 0
    luarc = json.loads((tmp_path / "demo" / ".luarc.json").read_text())["diagnostics.globals"]
    config = essaim("devices", "--luacheck").stdout
    hooks = config.split("globals = {", 1)[1].split("}", 1)[0]
    assert sorted(luarc) == sorted(h.strip().strip('"') for h in hooks.split(",")), (luarc, hooks)
