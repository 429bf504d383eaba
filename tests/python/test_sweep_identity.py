"""Run identity in scripts/sweep.py: a stored run is redone, with one line per cause, when a
file it read changed or is gone, or when essaim's version or the sweep's settings differ;
the other stored runs are reused."""
import json
import shutil
from collections import Counter
from pathlib import Path

import pytest

from conftest import ROOT, load_module, need_python_deps, run_sweep

need_python_deps()
import pandas as pd  # noqa: E402

sweep = load_module("sweep")


def test_fnv1a64_is_essaims():
    # Published FNV-1a 64 test vectors.
    assert sweep.fnv1a64(b"") == "fnv1a64:cbf29ce484222325"
    assert sweep.fnv1a64(b"a") == "fnv1a64:af63dc4c8601ec8c"
    assert sweep.fnv1a64(b"foobar") == "fnv1a64:85944171f73967e8"


def fake_run(run_dir: Path, inputs: dict, argv, version="1.0", **summary):
    """A finished run folder as essaim and the sweep leave it."""
    run_dir.mkdir(parents=True)
    listed = [{"path": str(p), "role": "controller", "hash": h} for p, h in inputs.items()]
    (run_dir / "summary.json").write_text(json.dumps(
        {"essaim_version": version, "status": "ok", "inputs": listed, **summary}))
    (run_dir / "sweep-run.json").write_text(json.dumps({"argv": argv, "returncode": 0}))


def test_stale_causes_name_each_changed_or_missing_file(tmp_path):
    a, b, c = tmp_path / "a.lua", tmp_path / "b.lua", tmp_path / "c.lua"
    a.write_text("x = 1")
    b.write_text("y = 2")
    summary = {"essaim_version": "1.0",
               "inputs": [{"path": str(p), "hash": sweep.fnv1a64(p.read_bytes())}
                          for p in (a, b)] + [{"path": str(c), "hash": "fnv1a64:0"}]}
    hashes = sweep.InputHashes()
    assert sweep.stale_causes(summary, a, "1.0", hashes) == [f"{c} is missing"]
    b.write_text("y = 3")
    causes = sweep.stale_causes(summary, a, "1.1", sweep.InputHashes())
    assert causes == ["essaim version changed (1.0 -> 1.1)", f"{b} changed", f"{c} is missing"]
    # No version to compare with (a binary only on the cluster): not a cause.
    assert sweep.stale_causes(summary, a, None, sweep.InputHashes()) == \
        [f"{b} changed", f"{c} is missing"]


def test_a_summary_without_inputs_is_judged_by_its_experiment_file(tmp_path):
    exp = tmp_path / "x.argos"
    exp.write_text("<argos-configuration/>")
    summary = {"essaim_version": "1.0", "experiment": str(exp),
               "experiment_hash": sweep.fnv1a64(exp.read_bytes())}
    assert sweep.stale_causes(summary, exp, "1.0", sweep.InputHashes()) == []
    exp.write_text("<argos-configuration />")
    assert sweep.stale_causes(summary, exp, "1.0", sweep.InputHashes()) == [f"{exp} changed"]


def test_plan_redoes_only_the_runs_whose_inputs_changed(tmp_path):
    ctrl, mod = tmp_path / "ctrl.lua", tmp_path / "mod.lua"
    ctrl.write_text("function step() end")
    mod.write_text("return {}")
    exp = tmp_path / "x.argos"
    exp.write_text("<argos-configuration/>")
    s = sweep.Sweep(path=tmp_path / "s.toml", experiment=exp, params={"a.b.c": [1, 2]},
                    seeds=[1, 2], out=tmp_path / "out", workdir=tmp_path)
    runs = s.runs()
    h = {p: sweep.fnv1a64(p.read_bytes()) for p in (ctrl, mod, exp)}
    for r in runs:
        # Runs of the point c=2 read the module too; the others only the controller.
        reads = {exp: h[exp], ctrl: h[ctrl], **({mod: h[mod]} if r.params["a.b.c"] == 2 else {})}
        fake_run(s.out / "runs" / r.key, reads, sweep.record_argv(s.argv(r, "essaim", "")))
    todo, causes = sweep.plan_runs(s, runs, "essaim", "1.0")
    assert todo == [] and causes == Counter()

    mod.write_text("return {edited = true}")
    todo, causes = sweep.plan_runs(s, runs, "essaim", "1.0")
    assert [r.key for r in todo] == ["c=2__seed=1", "c=2__seed=2"]
    assert causes == Counter({f"{mod} changed": 2})

    ctrl.unlink()
    todo, causes = sweep.plan_runs(s, runs, "essaim", "1.0")
    assert len(todo) == 4 and causes == Counter({f"{ctrl} is missing": 4, f"{mod} changed": 2})

    # Other settings (ticks): the sweep's record of the command line says so.
    ctrl.write_text("function step() end")
    mod.write_text("return {}")
    s.ticks = 7
    todo, causes = sweep.plan_runs(s, runs, "essaim", "1.0")
    assert len(todo) == 4 and causes == Counter({"sweep settings changed (now --ticks 7)": 4})


# ---------------------------------------------------------------------------------------
# On the shipped foraging arena, through essaim


def shipped_copy(tmp_path: Path) -> Path:
    """arenas/ and controllers/ copied, so the test can edit them."""
    for d in ("arenas", "controllers"):
        shutil.copytree(ROOT / d, tmp_path / d)
    return tmp_path


def foraging_sweep(root: Path) -> Path:
    path = root / "tiny.toml"
    path.write_text('experiment = "arenas/foraging.argos"\nworkdir = "."\nout = "out"\n'
                    'ticks = 20\nseeds = 2\n'
                    '[params]\n"arena.distribute.entity.quantity" = [2, 3]\n')
    return path


def table(root: Path):
    return pd.read_parquet(root / "out" / "results.parquet").set_index("run")


def test_editing_the_controller_or_a_required_module_redoes_the_runs(tmp_path, essaim,
                                                                     monkeypatch):
    root = shipped_copy(tmp_path)
    monkeypatch.chdir(root)  # messages name files relative to the current folder
    s = foraging_sweep(root)
    r = run_sweep(s, "-j", "2", essaim=essaim)
    assert r.returncode == 0, r.stderr
    summary = json.loads(next((root / "out" / "runs").glob("*/summary.json")).read_text())
    exp_bytes = (root / "arenas" / "foraging.argos").read_bytes()
    assert summary["experiment_hash"] == sweep.fnv1a64(exp_bytes)  # the same hash as essaim's
    before = table(root)
    assert (before["controller_error_count"] == 0).all()

    # The experiment file itself (listed by every essaim): all four runs are redone.
    (root / "arenas" / "foraging.argos").write_bytes(exp_bytes + b"<!-- edited -->\n")
    r = run_sweep(s, "-j", "2", essaim=essaim)
    assert r.returncode == 0, r.stderr
    assert "arenas/foraging.argos changed: redoing 4 runs" in r.stderr, r.stderr
    assert "0 already done, 4 to run" in r.stderr
    r = run_sweep(s, essaim=essaim)
    assert "4 already done, 0 to run" in r.stderr and "redoing" not in r.stderr

    if "inputs" not in summary:
        pytest.skip("this essaim's summary.json lists no `inputs`: the controller and module "
                    "cases need an essaim that does")
    listed = {Path(i["path"]).name for i in summary["inputs"]}
    assert {"foraging.argos", "foraging.lua", "config.lua", "foraging_loop.lua"} <= listed

    # The controller: robot fb0 now stops with an error at its first step.
    ctrl = root / "controllers" / "foraging.lua"
    ctrl.write_text(ctrl.read_text() + '\nlocal step0 = step\nfunction step()\n'
                    '  if robot.id == "fb0" then error("edited controller") end\n'
                    '  step0()\nend\n')
    r = run_sweep(s, "-j", "2", essaim=essaim)
    assert r.returncode == 0, r.stderr
    assert "controllers/foraging.lua changed: redoing 4 runs" in r.stderr, r.stderr
    after = table(root)
    assert (after["controller_error_count"] == 1).all()  # the results changed

    # A module the controller requires: every robot's init() now fails.
    config = root / "controllers" / "foraging" / "config.lua"
    text = config.read_text()
    assert text.rstrip().endswith("return M")
    config.write_text(text.rstrip()[:-len("return M")]
                      + 'function M.load() error("edited module") end\nreturn M\n')
    r = run_sweep(s, "-j", "2", essaim=essaim)
    assert r.returncode == 0, r.stderr
    assert "controllers/foraging/config.lua changed: redoing 4 runs" in r.stderr, r.stderr
    after = table(root)
    assert after["controller_error_count"].tolist() == after["robots"].tolist()
