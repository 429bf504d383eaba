"""The `essaim` module's API: shapes, dtypes, errors, context manager, threads, and equality
with `essaim run` for one seed."""
import json
import subprocess
import threading

import numpy as np
import pytest

from module_paths import FORAGING, SMALL

essaim = pytest.importorskip("essaim")


def test_arrays_have_the_documented_shapes_and_dtypes():
    with essaim.Simulation(FORAGING, seed=3, overrides=SMALL) as sim:
        assert sim.tick == 0
        assert sim.robot_ids == [f"fb{i}" for i in range(5)]
        assert sim.step(7) == 7 and sim.tick == 7
        poses, alive, battery, leds = sim.poses(), sim.alive(), sim.battery(), sim.led_colors()
        assert poses.shape == (5, 3) and poses.dtype == np.float64
        assert alive.shape == (5,) and alive.dtype == np.bool_ and alive.all()
        assert battery.shape == (5,) and battery.dtype == np.float64
        assert leds.shape == (5, 13, 3) and leds.dtype == np.uint8
        # <distribute> puts robots in [-1.2, 1.2]^2; delta 0.002 per tick from a full battery
        assert np.all(np.abs(poses[:, :2]) < 1.3)
        # fb1 starts in the nest, where the loop functions refill it every tick
        assert battery[[0, 2, 3, 4]] == pytest.approx(1 - 7 * 0.002) and battery[1] == 1.0
        # fresh arrays: keeping one does not see later ticks
        kept = sim.poses()
        sim.step(20)
        assert np.array_equal(kept, poses) and not np.array_equal(sim.poses(), kept)


def test_run_goes_to_the_end_and_finish_returns_metrics_and_summary():
    over = dict(SMALL, **{"framework.experiment.length": 30})  # seconds: 300 ticks
    with essaim.Simulation(FORAGING, seed=1, overrides=over) as sim:
        assert sim.run() == 300 and sim.tick == 300 and sim.finished
        assert sim.step(5) == 0  # nothing left to step
        metrics = sim.finish()
        assert metrics["robots"] == 5 and metrics["ticks"] == 300
        assert "trips_per_robot_mean" in metrics
        assert sim.summary["status"] == "ok" and sim.summary["finished_by"] == "length"
        assert sim.summary["seed"] == 1 and sim.summary["robots"] == 5


def test_summary_before_finish_says_running_and_closed_simulation_raises():
    sim = essaim.Simulation(FORAGING, seed=1, overrides=SMALL)
    assert sim.summary["status"] == "running" and sim.summary["ticks"] == 0
    with sim:
        pass
    with pytest.raises(essaim.Error, match="closed"):
        sim.step()


def test_errors_carry_the_cli_messages(essaim_bin, tmp_path):
    with pytest.raises(essaim.Error, match="nope.argos"):
        essaim.Simulation(str(tmp_path / "nope.argos"))
    over = {"arena.nosuch.x": 1}
    with pytest.raises(essaim.Error) as err:
        essaim.Simulation(FORAGING, overrides=over)
    cli = subprocess.run([essaim_bin, "check", FORAGING, "--set", "arena.nosuch.x=1"],
                         capture_output=True, text=True)
    assert cli.returncode == 2
    assert str(err.value).strip() == cli.stderr.strip()
    assert "no element at 'arena.nosuch'" in str(err.value)


def test_lua_error_names_robot_script_and_line(tmp_path):
    script = tmp_path / "broken.lua"
    script.write_text("function init() end\nfunction step()\n  error('boom')\nend\n"
                      "function reset() end\nfunction destroy() end\n")
    over = dict(SMALL, **{"controllers.foraging.params.script": str(script)})
    with essaim.Simulation(FORAGING, seed=1, overrides=over) as sim:
        sim.step(3)  # controller errors do not stop the run (CLI: without --strict)
        sim.finish()
        errors = sim.summary["controller_errors"]
        assert errors and "broken.lua:3" in json.dumps(errors) and "boom" in json.dumps(errors)


def test_two_simulations_in_threads_match_sequential_runs():
    def final(seed):
        with essaim.Simulation(FORAGING, seed=seed, overrides=SMALL) as sim:
            sim.step(400)
            return sim.poses(), sim.finish()

    expected = [final(1), final(2)]
    got = [None, None]

    def work(i):
        got[i] = final(i + 1)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for (p1, m1), (p2, m2) in zip(expected, got):
        assert np.array_equal(p1, p2) and m1 == m2


def test_same_seed_same_result_as_the_cli_whatever_the_threads(essaim_bin, tmp_path):
    over = dict(SMALL, **{"framework.experiment.length": 40})
    cli_out = tmp_path / "cli"
    args = [a for k, v in over.items() for a in ("--set", f"{k}={v}")]
    subprocess.run([essaim_bin, "run", FORAGING, "--seed", "4", "--threads", "1", "--quiet",
                    "--out", str(cli_out)] + args, check=True)
    for threads in (1, 2):
        py_out = tmp_path / f"py{threads}"
        with essaim.Simulation(FORAGING, seed=4, threads=threads, overrides=over, out=str(py_out)) as sim:
            sim.run()
            metrics = sim.finish()
        assert metrics == json.loads((cli_out / "metrics.json").read_text())
        assert (py_out / "metrics.json").read_bytes() == (cli_out / "metrics.json").read_bytes()
        assert (py_out / "timeseries.csv").read_bytes() == (cli_out / "timeseries.csv").read_bytes()


def test_unknown_attributes_warn_and_strict_refuses(tmp_path):
    with pytest.raises(essaim.Error, match="did you mean 'quantity'"):
        essaim.Simulation(FORAGING, overrides={"arena.distribute.entity.quantiy": 5})
    text = open(FORAGING).read().replace("<arena ", '<arena sise="1,1,1" ', 1)
    typo = tmp_path / "typo.argos"
    typo.write_text(text)
    scripts = {"script=\"": f"script=\"{FORAGING.rsplit('/', 1)[0]}/"}
    for a, b in scripts.items():
        typo.write_text(typo.read_text().replace(a, b))
    with pytest.warns(UserWarning, match="unknown attribute 'sise'.*did you mean 'size'"):
        essaim.Simulation(str(typo), overrides=SMALL).close()
    with pytest.raises(essaim.Error, match="unknown attribute 'sise'"):
        essaim.Simulation(str(typo), overrides=SMALL, strict=True)


def test_out_is_checked_and_an_earlier_runs_outputs_are_moved_aside(tmp_path):
    over = dict(SMALL, **{"framework.experiment.length": 1})
    (tmp_path / "a-file").write_text("x")
    with pytest.raises(essaim.Error, match="is a file, not a folder"):
        essaim.Simulation(FORAGING, seed=1, overrides=over, out=str(tmp_path / "a-file"))
    out = tmp_path / "o"
    out.mkdir()
    (out / "recording.bin").write_bytes(b"old")
    (out / "mine.txt").write_text("kept")
    with pytest.warns(UserWarning, match="moved them into .*previous: recording.bin"):
        sim = essaim.Simulation(FORAGING, seed=1, overrides=over, out=str(out))
    with sim:
        sim.run()
        sim.finish()
    assert (out / "previous" / "recording.bin").read_bytes() == b"old"
    assert not (out / "recording.bin").exists() and (out / "mine.txt").exists()
    assert (out / "summary.json").is_file()
