"""The engine's outputs.py (standard library, no SIERRA needed): a run's JSON numbers as the
one-row CSVs SIERRA reads, and an experiment's runs given the columns they share."""
import importlib.util
import json

from sierra_support import PLUGINS, read_csv

spec = importlib.util.spec_from_file_location("outputs", PLUGINS / "engine/essaim/outputs.py")
outputs = importlib.util.module_from_spec(spec)
spec.loader.exec_module(outputs)


def run_dir(folder, metrics, status="ok"):
    folder.mkdir(parents=True)
    (folder / "summary.json").write_text(json.dumps({"status": status, "ticks": 200,
                                                     "stage_seconds": {"physics": 0.5}}))
    (folder / "metrics.json").write_text(json.dumps(metrics))
    return folder


def test_numbers_two_levels_deep_as_floats(tmp_path):
    out = run_dir(tmp_path / "r", {"trips_total": 3, "ok": True, "name": "x", "list": [1],
                                   "trips_per_source": {"A": 2, "B": 1},
                                   "first_touch_by_robot": {"fb0": {"tick": 82}}})
    assert outputs.main(["outputs.py", str(out)]) == 0
    assert read_csv(out / "metrics.csv") == [{"ok": "1.0", "trips_per_source.A": "2.0",
                                              "trips_per_source.B": "1.0", "trips_total": "3.0"}]
    assert read_csv(out / "run.csv") == [{"stage_seconds.physics": "0.5", "ticks": "200.0"}]


def test_a_run_that_failed_fails_its_line(tmp_path):
    out = run_dir(tmp_path / "r", {"trips_total": 0}, status="controller_error")
    assert outputs.main(["outputs.py", str(out)]) == 1
    assert (out / "metrics.csv").exists()  # written all the same, for a look


def test_align_keeps_the_columns_every_run_has(tmp_path):
    exp = tmp_path / "exp-outputs" / "c1-exp0"
    for k, metrics in enumerate(({"a": 1, "first": 82}, {"a": 2})):
        outputs.convert(run_dir(exp / f"foraging_run{k}_output" / "essaim", metrics))
    assert outputs.main(["outputs.py", "--align", str(tmp_path / "exp-outputs")]) == 0
    for k, a in ((0, "1.0"), (1, "2.0")):
        assert read_csv(exp / f"foraging_run{k}_output/essaim/metrics.csv") == [{"a": a}]
