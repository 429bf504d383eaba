"""Stage 1 alone (fast): what the essaim engine writes into each run's .argos file for the
batch criteria of SIERRA's ARGoS engine and essaim's own `set.PATH=VALUES`, and that essaim
accepts every file it generates (`essaim check`)."""
import subprocess
import xml.etree.ElementTree as ET

from sierra_support import TEMPLATE, batch_root, essaim_binary, sierra_cli, sierra_env

BASE = ["--project=projects.foraging", "--engine=engine.essaim", f"--expdef-template={TEMPLATE}",
        "--n-runs=1", "--exp-setup=exp_setup.T1.K10", "--execenv=hpc.local",
        "--physics-n-engines=1", "--pipeline", "1"]


def generate(tmp_path, criterion, *extra):
    sierra_cli([*BASE, "--batch-criteria", criterion, f"--sierra-root={tmp_path}", *extra],
               sierra_env(), tmp_path)
    root = batch_root(tmp_path)
    files = sorted((root / "exp-inputs").rglob("foraging_run0.argos"))
    for f in files:
        r = subprocess.run([str(essaim_binary()), "check", str(f), "--ticks", "2"],
                           capture_output=True, text=True, timeout=120)
        assert r.returncode == 0, f"{f}: {r.stdout}{r.stderr}"
    return root, [ET.parse(f).getroot() for f in files]


def test_paths_seed_length_and_devices(tmp_path):
    root, (xml,) = generate(tmp_path, "population_size.Linear3.C1")
    assert xml.find(".//arena/distribute/entity").get("quantity") == "3"
    assert xml.find(".//experiment").get("length") == "1"
    script = xml.find(".//lua_controller/params").get("script")
    assert script == str((TEMPLATE.parent / "../controllers/foraging.lua").resolve())
    assert xml.find(".//loop_functions").get("script").startswith("/")
    # ARGoS's engine drops these unless --with-robot-*; essaim keeps the template's.
    assert xml.find(".//media/range_and_bearing") is not None
    assert xml.find(".//actuators/leds") is not None
    cmds = (root / "exp-inputs" / "c1-exp0" / "commands.txt").read_text()
    assert " run " in cmds and "--threads 1" in cmds and "outputs.py" in cmds


def test_set_criterion_gives_one_experiment_per_value(tmp_path):
    _, xmls = generate(tmp_path, "set.controllers.foraging.params.EPSILONGREED=0.1,0.5")
    assert [x.find(".//lua_controller/params").get("EPSILONGREED") for x in xmls] == ["0.1", "0.5"]


def test_constant_density_grows_arena_walls_and_swarm(tmp_path):
    _, xmls = generate(tmp_path, "population_constant_density.10p0.I4.C2",
                       "--scenario=foraging.10x10x1")
    sizes = [x.find(".//arena").get("size") for x in xmls]
    assert sizes == ["10,10,1", "14,14,1"]
    assert [x.find(".//arena/distribute/entity").get("quantity") for x in xmls] == ["10", "19"]
    north = xmls[1].find(".//arena/box[@id='wall_north']/body").get("position")
    assert north == "0,6.95,0"


def test_monte_carlo_with_n_agents(tmp_path):
    _, xmls = generate(tmp_path, "builtin.MonteCarlo.C2", "--n-agents=3")
    assert [x.find(".//arena/distribute/entity").get("quantity") for x in xmls] == ["3", "3"]
