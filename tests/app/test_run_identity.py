"""summary.json lists every file a run read with the hash of its bytes, and a run identity
that changes when any of them, the overrides, the length or the seed change."""
import os

from clitest import CONTROLLER, argos, fnv1a64, need_essaim, run, write

pytestmark = need_essaim

MODULE_USER = """
local helper = require("lib.helper")
function init() helper.setup() end
function step() robot.wheels.set_velocity(helper.speed, helper.speed) end
"""
HELPER = "local M = {speed = 5}\nfunction M.setup() end\nreturn M\n"
LOOP = """
local util = require("loop_util")
function init() end
function post_step() return util.done() end
"""


def by_role(summary):
    return {(f["role"], os.path.basename(f["path"])): f for f in summary["inputs"]}


def test_inputs_list_every_file_with_its_hash(tmp_path):
    write(tmp_path, {
        "x.argos": argos(loop='<loop_functions script="loop.lua" />'),
        "c.lua": MODULE_USER, "lib/helper.lua": HELPER, "loop.lua": LOOP,
        "loop_util.lua": "return {done = function() return false end}\n"})
    r, s = run(tmp_path, "x.argos")
    assert r.returncode == 0, r.stderr
    inputs = by_role(s)
    assert set(inputs) == {("arena", "x.argos"), ("controller", "c.lua"), ("loop_functions", "loop.lua"),
                           ("module", "helper.lua"), ("module", "loop_util.lua")}, s["inputs"]
    for f in s["inputs"]:
        assert os.path.isabs(f["path"]) and os.path.realpath(f["path"]) == f["path"]
        assert f["hash"] == fnv1a64(open(f["path"], "rb").read()), f
    assert inputs[("module", "helper.lua")]["path"] == str((tmp_path / "lib/helper.lua").resolve())
    assert s["run_identity"].startswith("fnv1a64:") and len(s["run_identity"]) == len("fnv1a64:") + 16


def test_identity_changes_with_a_module_the_overrides_and_the_seed(tmp_path):
    write(tmp_path, {"x.argos": argos(), "c.lua": MODULE_USER, "lib/helper.lua": HELPER})
    identities = []

    def identity(*args):
        r, s = run(tmp_path, "x.argos", *args)
        assert r.returncode == 0, r.stderr
        identities.append(s["run_identity"])
        return s

    first = identity()
    again = identity()
    assert again["run_identity"] == first["run_identity"]  # same files, same identity
    (tmp_path / "lib/helper.lua").write_text(HELPER.replace("speed = 5", "speed = 6"))
    edited = identity()
    assert by_role(edited)[("module", "helper.lua")]["hash"] != by_role(first)[("module", "helper.lua")]["hash"]
    identity("--seed", "2")
    identity("--ticks", "2")
    identity("--set", "controllers.c.params.speed=3")
    assert len(set(identities)) == len(identities) - 1, identities


def test_identity_ignores_threads(tmp_path):
    write(tmp_path, {"x.argos": argos(), "c.lua": CONTROLLER})
    one = run(tmp_path, "x.argos", "--threads", "1")[1]
    two = run(tmp_path, "x.argos", "--threads", "2")[1]
    assert one["run_identity"] == two["run_identity"]


def test_a_failure_summary_lists_the_files_read_so_far(tmp_path):
    # The module is read, then fails: bad input (exit 2), and the summary says which files.
    write(tmp_path, {"x.argos": argos(), "c.lua": MODULE_USER, "lib/helper.lua": "return {speed = }\n"})
    r, s = run(tmp_path, "x.argos")
    assert r.returncode == 2, r.stderr
    assert s["status"] == "failed"
    assert ("controller", "c.lua") in by_role(s) and ("arena", "x.argos") in by_role(s)
    assert "run_identity" in s


def test_a_module_required_in_step_on_several_threads_is_listed_once(tmp_path):
    lazy = "function init() end\nfunction step() local h = require('lib.helper') robot.wheels.set_velocity(h.speed, 0) end\n"
    write(tmp_path, {"x.argos": argos(robots=6), "c.lua": lazy, "lib/helper.lua": HELPER})
    r, s = run(tmp_path, "x.argos", "--threads", "2")
    assert r.returncode == 0, r.stderr
    modules = [f for f in s["inputs"] if f["role"] == "module"]
    assert [os.path.basename(f["path"]) for f in modules] == ["helper.lua"]
    assert s["run_identity"] == run(tmp_path, "x.argos", "--threads", "1")[1]["run_identity"]
