"""scripts/optimise.py: a tiny study writes its database and best.json, then resumes."""
import json
import subprocess
import sys

import pytest

from module_paths import FORAGING, ROOT

pytest.importorskip("optuna")


def write_study(path):
    path.write_text(f'''experiment = "{FORAGING}"
workdir = "{ROOT}"
seeds = [1]
eval_seeds = [9]
[set]
"arena.distribute.entity.quantity" = 4
[params]
"controllers.foraging.params.EPSILONGREED" = {{ low = 0.0, high = 0.5 }}
"controllers.foraging.params.INIT_BATT_SEC" = {{ low = 5, high = 60 }}
''')
    return path


def optimise(*args):
    return subprocess.run([sys.executable, str(ROOT / "scripts" / "optimise.py"), *args],
                          capture_output=True, text=True, cwd=ROOT)


@pytest.mark.parametrize("backend", ["module", "cli"])
def test_tiny_study_writes_db_and_best_then_resumes(tmp_path, backend, essaim_bin):
    if backend == "module":
        pytest.importorskip("essaim")
    study = write_study(tmp_path / "s.toml")
    out = tmp_path / "out"
    extra = ["--essaim", essaim_bin] if backend == "cli" else []
    p = optimise(str(study), "--trials", "3", "--ticks", "150", "--out", str(out), *extra)
    assert p.returncode == 0, p.stderr
    assert (out / "study.db").is_file()
    best = json.loads((out / "best.json").read_text())
    assert set(best["set"]) == {"arena.distribute.entity.quantity",
                                "controllers.foraging.params.EPSILONGREED",
                                "controllers.foraging.params.INIT_BATT_SEC"}
    assert isinstance(best["set"]["controllers.foraging.params.INIT_BATT_SEC"], int)
    assert best["args"][0] == "--set" and "=" in best["args"][1]
    ev = json.loads((out / "evaluation.json").read_text())
    assert ev["best"]["seeds"] == [9] and "trips_per_robot_mean" in ev["baseline"]
    p = optimise(str(study), "--trials", "5", "--ticks", "150", "--out", str(out), "--no-eval", *extra)
    assert p.returncode == 0, p.stderr
    assert "3 trial(s) stored" in p.stdout and "running 2 more" in p.stdout
    import optuna
    st = optuna.load_study(study_name="essaim", storage=f"sqlite:///{out / 'study.db'}")
    assert len(st.trials) == 5


def test_multi_objective_writes_a_pareto_front(tmp_path):
    pytest.importorskip("essaim")
    out = tmp_path / "out"
    p = optimise(str(write_study(tmp_path / "s.toml")), "--multi", "--trials", "3", "--ticks", "150",
                 "--out", str(out), "--no-eval")
    assert p.returncode == 0, p.stderr
    best = json.loads((out / "best.json").read_text())
    assert best["pareto_front"] and all("deaths" in t for t in best["pareto_front"])
    # resuming with the other mode is refused, not mixed
    p = optimise(str(write_study(tmp_path / "s.toml")), "--trials", "4", "--out", str(out))
    assert p.returncode == 2 and "--multi" in p.stderr


def test_overlapping_seeds_are_refused(tmp_path):
    p = optimise(str(write_study(tmp_path / "s.toml")), "--seeds", "1,9", "--out", str(tmp_path / "o"))
    assert p.returncode == 2 and "overlap" in p.stderr


def test_plot_study_draws_history_importances_and_pareto(tmp_path):
    pytest.importorskip("essaim")
    pytest.importorskip("matplotlib")
    out = tmp_path / "out"
    p = optimise(str(write_study(tmp_path / "s.toml")), "--multi", "--trials", "3", "--ticks", "100",
                 "--out", str(out), "--no-eval")
    assert p.returncode == 0, p.stderr
    p = subprocess.run([sys.executable, str(ROOT / "scripts" / "plot_study.py"), str(out)],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    for name in ("history.png", "importances.png", "pareto.png"):
        assert (out / name).read_bytes()[:4] == b"\x89PNG"
    p = subprocess.run([sys.executable, str(ROOT / "scripts" / "plot_study.py"), str(tmp_path / "none")],
                       capture_output=True, text=True)
    assert p.returncode == 2 and "no study database" in p.stderr


def test_a_resumed_study_redoes_the_trials_whose_files_or_settings_changed(tmp_path):
    pytest.importorskip("essaim")
    import shutil
    for d in ("arenas", "controllers"):
        shutil.copytree(ROOT / d, tmp_path / d)
    argos = tmp_path / "arenas" / "foraging.argos"
    study = tmp_path / "s.toml"
    study.write_text(write_study(tmp_path / "x.toml").read_text()
                     .replace(f'"{FORAGING}"', f'"{argos}"').replace(f'"{ROOT}"', f'"{tmp_path}"'))
    out = tmp_path / "out"

    def run(*extra):
        p = subprocess.run([sys.executable, str(ROOT / "scripts" / "optimise.py"), str(study),
                            "--trials", "2", "--ticks", "30", "--out", str(out), "--no-eval",
                            *extra], capture_output=True, text=True, cwd=tmp_path)
        assert p.returncode == 0, p.stderr
        return p.stdout

    import optuna

    def trials():
        st = optuna.load_study(study_name="essaim", storage=f"sqlite:///{out / 'study.db'}")
        return [t for t in st.trials if t.state == optuna.trial.TrialState.COMPLETE]

    run()
    first = trials()
    assert len(first) == 2 and all("identity" in t.user_attrs for t in first)
    listed = {i["path"] for i in first[0].user_attrs["identity"]["inputs"]}
    assert str(argos) in listed
    assert "redoing" not in run()  # nothing changed: both trials stand

    argos.write_text(argos.read_text() + "<!-- edited -->\n")
    text = run()
    assert "arenas/foraging.argos changed: redoing 2 trials" in text, text
    assert (out / "study-stale-1.db").is_file()
    again = trials()
    assert [t.params for t in again] == [t.params for t in first]  # the same points, rerun
    assert "running 2 more" in text

    text = run("--ticks", "40")
    assert "study settings changed (ticks): redoing 2 trials" in text, text
    assert (out / "study-stale-2.db").is_file() and len(trials()) == 2
