"""Files the loop functions write (docs/loop-functions.md, "Files the loop functions write"):
each run works in <out>/files/, a view of the experiment folder, and keeps there the files
it wrote, so that runs side by side never overwrite each other's; `essaim test` checks a
column of them; `essaim check` writes nothing anywhere the user keeps files."""
import json
import os
import shutil
from pathlib import Path

from clitest import essaim, need_essaim

pytestmark = need_essaim

PROJECT = Path(__file__).resolve().parent / "zones_project"


def project(tmp_path: Path) -> Path:
    """A copy of zones_project, holding an earlier result of the same name as the runs'."""
    folder = tmp_path / "zones"
    shutil.copytree(PROJECT, folder)
    (folder / "zone_counts.txt").write_text("an earlier ARGoS run's results\n")
    return folder


def listing(*folders: Path) -> dict:
    """Every path below the folders, with its kind, size and modification time."""
    seen = {}
    for folder in folders:
        for root, dirs, files in os.walk(folder):
            for name in dirs + files:
                p = Path(root) / name
                st = p.lstat()
                seen[str(p)] = (st.st_mode, st.st_size, st.st_mtime_ns)
    return seen


def table(path: Path) -> list[dict]:
    header, *rows = path.read_text().splitlines()
    return [dict(zip(header.split(), map(int, row.split()))) for row in rows]


def test_each_seed_keeps_its_own_file_and_a_column_is_checked(tmp_path):
    folder = project(tmp_path)
    before = listing(folder)
    r = essaim("test", folder / "zones.test.toml", "-j", "2", "--out", tmp_path / "t", cwd=tmp_path, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "6 of 6 expectations hold" in r.stdout
    for seed in (1, 2, 3, 4):
        run = tmp_path / "t" / f"seed-{seed}"
        rows = table(run / "files" / "zone_counts.txt")
        assert [row["tick"] for row in rows] == list(range(1, 21))
        assert {row["seed"] for row in rows} == {seed}  # its own run's file, not another seed's
        assert json.loads((run / "summary.json").read_text())["files"] == ["files/zone_counts.txt"]
        assert sorted(p.name for p in (run / "files").iterdir()) == ["zone_counts.txt"]  # the view is gone
    assert listing(folder) == before  # the earlier results of the same name untouched
    assert (folder / "zone_counts.txt").read_text() == "an earlier ARGoS run's results\n"


def test_a_missing_file_or_column_names_the_spec_line(tmp_path):
    folder = project(tmp_path)
    spec = folder / "zones.test.toml"
    spec.write_text('experiment = "zones.argos"\nseeds = 2\nticks = 3\nexpect = [\n'
                    '  "each files/nope.txt[tick].last == 3",\n'
                    '  "mean files/zone_counts.txt[nocol].last > 0",\n'
                    '  "each files/zone_counts.txt[1].last == 3",\n'
                    '  "fraction(files/zone_counts.txt[tick].sum/ticks > 1) == 1",\n]\n')
    r = essaim("test", spec, "-j", "2", "--out", tmp_path / "t", cwd=tmp_path, timeout=300)
    assert r.returncode == 1, r.stdout + r.stderr
    assert f"{spec}:5: seed 1: files/nope.txt: the run wrote no such file (it wrote files/zone_counts.txt)" in r.stdout
    assert f"{spec}:6: seed 2: files/zone_counts.txt: no column 'nocol' (columns: tick, inside, zones, seed)" \
        in r.stdout
    assert "3 of 5 expectations hold" in r.stdout  # a column by position; a file column over ticks (6/3)

    spec.write_text('experiment = "zones.argos"\nexpect = [\n  "each files/zone_counts.txt[tick] == 3",\n]\n')
    r = essaim("test", spec, cwd=tmp_path)
    assert r.returncode == 2
    assert f"{spec}:3:" in r.stderr and "after the column comes .last, .first" in r.stderr


def test_a_run_reads_beside_its_argos_file_and_writes_into_its_out_folder(tmp_path):
    folder = project(tmp_path)
    before = listing(folder)
    r = essaim("run", "zones/zones.argos", "-q", "--ticks", 20, "--out", "o", cwd=tmp_path)  # from the folder above
    assert r.returncode == 0, r.stderr
    rows = table(tmp_path / "o" / "files" / "zone_counts.txt")  # data/zones.txt and the helper were read
    assert len(rows) == 20 and all(row["zones"] == 2 for row in rows)
    assert sorted(p.name for p in (tmp_path / "o" / "files").iterdir()) == ["zone_counts.txt"]
    assert listing(folder) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["o", "zones"]

    r = essaim("run", "zones/zones.argos", "-q", "--ticks", 20, "--out", "o", "--seed", "5", cwd=tmp_path)
    assert r.returncode == 0, r.stderr  # the first run's files go into previous/ with its outputs
    assert table(tmp_path / "o" / "previous" / "files" / "zone_counts.txt")[0]["seed"] == 1
    assert table(tmp_path / "o" / "files" / "zone_counts.txt")[0]["seed"] == 5


def test_a_file_the_run_changes_is_its_own_copy(tmp_path):
    folder = project(tmp_path)
    (folder / "zones_loop.lua").write_text(
        (folder / "zones_loop.lua").read_text()
        + 'local f = assert(io.open("data_note.txt", "a")) f:write("appended\\n") f:close()\n')
    (folder / "data_note.txt").write_text("the user's\n")
    r = essaim("run", "zones.argos", "-q", "--out", tmp_path / "o", cwd=folder)
    assert r.returncode == 0, r.stderr
    assert (folder / "data_note.txt").read_text() == "the user's\n"
    assert (tmp_path / "o" / "files" / "data_note.txt").read_text() == "the user's\nappended\n"
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert summary["files"] == ["files/data_note.txt", "files/zone_counts.txt"]


def test_check_leaves_the_experiment_and_launch_folders_as_they_were(tmp_path):
    folder = project(tmp_path)
    before = listing(tmp_path)
    r = essaim("check", "zones/zones.argos", cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    assert listing(tmp_path) == before
    r = essaim("check", "zones.argos", cwd=folder)
    assert r.returncode == 0, r.stderr
    assert listing(tmp_path) == before


def test_a_failed_or_stuck_run_still_keeps_only_its_own_files(tmp_path):
    folder = project(tmp_path)
    loop = folder / "zones_loop.lua"
    loop.write_text(loop.read_text() + "local step = post_step\n"
                    "function post_step() step() if experiment.tick == 3 then error('broken at 3') end end\n")
    r = essaim("run", "zones.argos", "-q", "--out", tmp_path / "failed", cwd=folder)
    assert r.returncode == 1 and "broken at 3" in r.stderr
    summary = json.loads((tmp_path / "failed" / "summary.json").read_text())
    assert summary["status"] == "failed" and summary["files"] == ["files/zone_counts.txt"]
    assert sorted(p.name for p in (tmp_path / "failed" / "files").iterdir()) == ["zone_counts.txt"]

    # The watchdog's last resort (a call stuck inside C) ends the process at once: the view goes too.
    shutil.copy(PROJECT / "zones_loop.lua", loop)
    (folder / "zones_robot.lua").write_text(
        'function init() end\nfunction step()\n  string.find(string.rep("a", 40), string.rep("a*", 40) .. "b")\nend\n')
    r = essaim("run", "zones.argos", "-q", "--lua-seconds", "2", "--out", tmp_path / "stuck", cwd=folder)
    assert r.returncode == 1 and "stuck for" in r.stderr, r.stderr
    summary = json.loads((tmp_path / "stuck" / "summary.json").read_text())
    assert summary["files"] == ["files/zone_counts.txt"]
    assert sorted(p.name for p in (tmp_path / "stuck" / "files").iterdir()) == ["zone_counts.txt"]


def test_scripts_above_the_working_directory_are_still_found(tmp_path):
    """`script="../shared/..."` beside an .argos file started in its own folder: the run's
    folder has no `..` of the experiment's, so such paths are made absolute first."""
    folder = project(tmp_path)
    (tmp_path / "shared").mkdir()
    shutil.move(folder / "zones_robot.lua", tmp_path / "shared" / "zones_robot.lua")
    argos = folder / "zones.argos"
    argos.write_text(argos.read_text().replace('script="zones_robot.lua"', 'script="../shared/zones_robot.lua"'))
    for command in ("run", "check"):
        r = essaim(command, "zones.argos", *(["-q", "--out", tmp_path / "o"] if command == "run" else []), cwd=folder)
        assert r.returncode == 0, r.stderr
    assert len(table(tmp_path / "o" / "files" / "zone_counts.txt")) == 20
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert str(tmp_path / "shared" / "zones_robot.lua") in [i["path"] for i in summary["inputs"]]


def test_require_under_the_sandbox_finds_modules_of_the_experiment_folder(tmp_path):
    folder = project(tmp_path)
    (folder / "lib").mkdir()
    (folder / "lib" / "speed.lua").write_text("return {value = 3}\n")  # in a linked folder
    (folder / "turn.lua").write_text("return {value = 1}\n")  # a copied file
    (folder / "zones_robot.lua").write_text(
        'local speed, turn = require("lib.speed"), require("turn")\nfunction init() end\n'
        'function step() robot.wheels.set_velocity(speed.value, speed.value + turn.value) end\n')
    loop = folder / "zones_loop.lua"  # no io under the sandbox: the loop functions only count
    loop.write_text("function post_step() end\n")
    r = essaim("run", "zones.argos", "-q", "--sandbox", "--out", tmp_path / "o", cwd=folder)
    assert r.returncode == 0, r.stderr
    assert json.loads((tmp_path / "o" / "summary.json").read_text())["controller_errors"] == []
