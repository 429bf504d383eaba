"""Projects written for older ARGoS betas (docs/loop-functions.md, "Which ARGoS versions'
projects build"), each built untouched through pkg-config and run: loop functions of ARGoS
3.0.0-beta17 (m_cSpace, m_cSimulator, a body's GetPosition / GetOrientation /
GetInitPosition / SetPosition, MoveEntity with b_check_only), whose file of poses must equal
the one a Lua twin writes from essaim's own handles; and loop functions that reach CRandom and
CRange through loop_functions.h alone and add foot-bots with the constructors of three eras."""
import json
import math

import pytest

from argos_projects import HERE, build_project, need_essaim, run

pytestmark = need_essaim


@pytest.fixture(scope="module")
def legacy(tmp_path_factory):
    return build_project(HERE / "beta17_project", tmp_path_factory.mktemp("legacy"))


@pytest.fixture(scope="module")
def scatter(tmp_path_factory):
    return build_project(HERE / "rng_project", tmp_path_factory.mktemp("scatter"))


def poses(path):
    """{(tick, id): numbers} from a file of poses."""
    rows = {}
    for line in path.read_text().splitlines():
        tick, name, *numbers = line.split("\t")
        assert (int(tick), name) not in rows
        rows[int(tick), name] = [float(v) for v in numbers]
    return rows


def same(a, b, tolerance=1e-9):
    return len(a) == len(b) and all(math.isclose(x, y, abs_tol=tolerance) for x, y in zip(a, b))


def near(a, b):
    """Equal to what the .argos file or the loop functions asked (the world keeps floats)."""
    return same(a, b, 1e-6)


@pytest.fixture(scope="module")
def legacy_runs(legacy, tmp_path_factory):
    """The C++ loop functions' run and the Lua twin's: (process, C++ poses, Lua poses, out folder)."""
    tmp_path = tmp_path_factory.mktemp("legacy_runs")
    done = run(legacy / "legacy.argos", "--out", str(tmp_path / "cpp"), cwd=legacy)
    assert done.returncode == 0, done.stderr
    assert "warning" not in done.stderr  # every attribute of the file is read
    twin = (legacy / "legacy.argos").read_text().replace(
        'library="build/liblegacy_loop_functions" label="legacy_loop_functions"', 'script="legacy_twin.lua"')
    (legacy / "twin.argos").write_text(twin.replace('output="poses.txt"', 'output="twin_poses.txt"'))
    twin_done = run(legacy / "twin.argos", "--out", str(tmp_path / "lua"), cwd=legacy)
    assert twin_done.returncode == 0, twin_done.stderr
    # Each run's own files, in its working folder <out>/files (docs/loop-functions.md)
    cpp, lua = tmp_path / "cpp" / "files", tmp_path / "lua" / "files"
    return done, poses(cpp / "poses.txt"), poses(lua / "twin_poses.txt"), tmp_path


def test_beta17_loop_functions_read_what_essaim_handles_read(legacy_runs):
    done, cpp, lua, tmp_path = legacy_runs
    assert sorted(cpp) == sorted(lua) and len(cpp) == 21 * 5  # ticks 0 (Init) to 20, four robots and the light
    different = [key for key in cpp if not same(cpp[key], lua[key])]
    assert different == []
    assert "legacy: mt19937, seed 17, clock 0" in done.stdout
    summary = json.loads((tmp_path / "cpp" / "summary.json").read_text())
    assert summary["status"] == "ok" and summary["ticks"] == 20


def test_beta17_moves_and_init_poses(legacy_runs):
    done, cpp, _, _ = legacy_runs
    # MoveEntity(..., true) only checks; a place on top of fb0 is refused, the body stays.
    assert "legacy: fb3 fits yes, onto fb0 refused" in done.stdout
    assert near(cpp[0, "fb3"][:3], [-1.0, 1.0, math.pi / 2])
    assert near(cpp[0, "fb3"][3:], [1.5, 1.0, -math.pi / 2])  # GetInitPosition: where the file put it
    assert all(near(cpp[t, "fb1"][3:], [-0.5, -1.0, math.pi / 4]) for t in range(21))
    assert near(cpp[0, "beacon"], [1.5, 1.5]) and near(cpp[20, "beacon"], [1.5, 1.5])  # a light moves
    assert cpp[20, "fb0"][:2] != cpp[0, "fb0"][:2]  # the robots drive
    assert "legacy: post added at 0,-1.6" in done.stdout  # SetPosition before AddEntity: where it is added


def test_set_position_is_reported_until_the_physics_updates_the_body(legacy_runs):
    done, cpp, lua, _ = legacy_runs
    assert "legacy: fb0 reports 9,9 heading 180 after SetPosition" in done.stdout
    # At the next tick the physics' pose shows again: fb0 did not move to (9, 9).
    assert same(cpp[6, "fb0"], lua[6, "fb0"]) and math.hypot(*cpp[6, "fb0"][:2]) < 2
    # A static body's physics never updates it: what was set stays reported, the body stays put.
    assert "legacy: post reports 1.2,1.6, stands at 0,-1.6" in done.stdout


def scatter_rows(folder):
    rows = [line.split("\t") for line in (folder / "scatter.txt").read_text().splitlines()]
    return rows


def test_crandom_and_crange_come_with_loop_functions_h(scatter, tmp_path):
    done = run(scatter / "scatter.argos", "--out", str(tmp_path / "out"), cwd=scatter)
    assert done.returncode == 0, done.stderr
    rows = scatter_rows(tmp_path / "out" / "files")
    robots = [row for row in rows if row[0] == "robot"]
    assert [row[1] for row in robots] == ["early", "middle", "late"]  # three constructors
    assert all(row[4] == "in" and -1.5 <= float(row[3]) <= 1.5 for row in robots)
    dice = [int(row[1]) for row in rows if row[0] == "die"]
    assert len(dice) == 5 and all(1 <= d < 7 for d in dice)
    assert rows[-1] == ["robots", "4"]
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["status"] == "ok"
    again = run(scatter / "scatter.argos", "--out", str(tmp_path / "again"), cwd=scatter)
    again_rows = scatter_rows(tmp_path / "again" / "files")
    assert again.returncode == 0 and again_rows == rows  # the experiment's seed draws them
