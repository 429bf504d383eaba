"""The CLI11 command line (docs/cli.md): per-command help, value checks with true messages,
"did you mean", --set-file; JSON outputs that stay valid; paths with spaces and accents."""
import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

ESSAIM = os.environ.get("ESSAIM")
DATA = Path(__file__).resolve().parents[1] / "data"
ROOT = Path(__file__).resolve().parents[2]
pytestmark = pytest.mark.skipif(not ESSAIM, reason="ESSAIM (the essaim binary) is not set")


def run(*args, cwd=None):
    return subprocess.run([ESSAIM, *map(str, args)], capture_output=True, text=True, timeout=60, cwd=cwd)


@pytest.mark.parametrize("command", ["run", "check", "devices", "bench", "replay", "snapshot", "video"])
def test_every_command_has_its_own_help_with_an_example(command):
    r = run(command, "--help")
    assert r.returncode == 0, r.stderr
    assert f"essaim {command}" in r.stdout and "Example:" in r.stdout
    assert run("help", command).stdout == r.stdout


def test_help_lists_commands_and_version_answers():
    r = run("help")
    assert r.returncode == 0 and "snapshot" in r.stdout
    assert run("--version").stdout.startswith("essaim ")
    assert run("run", "--version").stdout == run("--version").stdout
    r = run()
    assert r.returncode == 2 and "Subcommands:" in r.stderr


def test_defaults_are_shown():
    out = run("snapshot", "--help").stdout
    assert "--size PX=1024" in out and "--trail N=0" in out


@pytest.mark.parametrize("args, message", [
    (["run", DATA / "tiny.argos", "--ticks", "0"], "--ticks: '0' is out of range: expected 1 to"),
    (["run", DATA / "tiny.argos", "--ticks", "-5"], "--ticks: '-5' is out of range"),
    (["run", DATA / "tiny.argos", "--threads", "0"], "--threads: '0' is out of range: expected 1 to 1024"),
    (["run", DATA / "tiny.argos", "--threads", "100000"], "--threads: '100000' is out of range: expected 1 to 1024"),
    (["run", DATA / "tiny.argos", "--seed", "abc"], "--seed: 'abc' is not a whole number"),
    (["run", DATA / "tiny.argos", "--tikcs", "5"], "unknown option --tikcs (did you mean --ticks?)"),
    (["run", DATA / "tiny.argos", "--recrod"], "unknown option --recrod (did you mean --record?)"),
    (["run", DATA / "tiny.argos", "--record", "every=0"], "--record: 'every=0' must be every=N"),
    (["run", DATA / "tiny.argos", "extra"], "unexpected argument extra"),
    (["snapshot", "x", "--size", "8"], "--size: '8' is out of range: expected 16 to 8192"),
    (["video", "x", "--fps", "500"], "--fps: '500' is out of range: expected 1 to 240"),
    (["video", "x", "--taril", "5"], "unknown option --taril (did you mean --trail?)"),
    (["bench", "--only", "nope"], "--only: nope not in"),
    (["rnu"], "unknown command 'rnu' (did you mean 'run'?)"),
    (["help", "chek"], "unknown command 'chek' (did you mean 'check'?)"),
])
def test_bad_values_exit_2_with_a_true_message(args, message):
    r = run(*args)
    assert r.returncode == 2, r.stderr
    assert message in r.stderr


def test_set_file_applies_overrides_before_set(tmp_path):
    params = tmp_path / "params.json"
    params.write_text(json.dumps({"controllers.ctrl.params.speed": 7.5, "framework.experiment.length": 2,
                                  "controllers.ctrl.params.fail": "0"}))
    r = run("run", "tiny.argos", "--quiet", "--out", tmp_path / "o", "--set-file", params,
            "--set", "framework.experiment.length=3", cwd=DATA)
    assert r.returncode == 0, r.stderr
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert summary["overrides"] == ["controllers.ctrl.params.speed=7.5", "framework.experiment.length=2",
                                    "controllers.ctrl.params.fail=0", "framework.experiment.length=3"]
    assert summary["ticks"] == 30
    assert run("check", "tiny.argos", "--set-file", params, cwd=DATA).returncode == 0


def test_set_file_nested_objects_are_path_segments(tmp_path):
    params = tmp_path / "params.json"
    params.write_text('{"framework": {"experiment": {"length": 1}}, "controllers.ctrl": {"params": {"speed": 2}}}')
    r = run("run", "tiny.argos", "--quiet", "--out", tmp_path / "o", "--set-file", params, cwd=DATA)
    assert r.returncode == 0, r.stderr
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())
    assert summary["overrides"] == ["framework.experiment.length=1", "controllers.ctrl.params.speed=2"]
    assert summary["ticks"] == 10


@pytest.mark.parametrize("content, message", [
    ('{"a.b": 1,}', "params.json: invalid JSON at line 1, column 11"),
    ('[1, 2]', "params.json: expected a JSON object"),
    ('{"arena": {"x": [1]}}', 'params.json: "arena.x": the value must be a string, a number or a boolean, not array'),
    ('{"arena.x": null}', 'params.json: "arena.x": the value must be a string, a number or a boolean, not null'),
])
def test_bad_set_file_exits_2(tmp_path, content, message):
    (tmp_path / "params.json").write_text(content)
    r = run("check", DATA / "tiny.argos", "--set-file", tmp_path / "params.json")
    assert r.returncode == 2
    assert message in r.stderr
    r = run("check", DATA / "tiny.argos", "--set-file", tmp_path / "missing.json")
    assert r.returncode == 2 and "missing.json: cannot read the --set-file" in r.stderr


def test_folder_with_spaces_and_accents_run_from_elsewhere(tmp_path):
    """Relative script and floor-image paths resolve beside the .argos file, whatever the cwd."""
    folder = tmp_path / "expériences été" / "sous dossier"
    folder.mkdir(parents=True)
    shutil.copy(DATA / "tiny.lua", folder / "contrôleur à vide.lua")
    shutil.copy(ROOT / "bench" / "rays_floor.png", folder / "sol clair.png")
    argos = (DATA / "tiny.argos").read_text().replace('script="tiny.lua"', 'script="contrôleur à vide.lua"')
    argos = argos.replace('<arena size="4, 4, 1" center="0, 0, 0.5">',
                          '<arena size="4, 4, 1" center="0, 0, 0.5">\n'
                          '    <floor id="floor" source="image" path="sol clair.png" />')
    (folder / "exp é.argos").write_text(argos)
    elsewhere = tmp_path / "ailleurs"
    elsewhere.mkdir()
    rel = Path("..") / "expériences été" / "sous dossier" / "exp é.argos"
    r = run("run", rel, "--quiet", "--out", "sortie ü", cwd=elsewhere)
    assert r.returncode == 0, r.stderr
    summary = json.loads((elsewhere / "sortie ü" / "summary.json").read_text())
    assert summary["status"] == "ok" and summary["robots"] == 4


def _loop_experiment(tmp_path, post_experiment):
    shutil.copy(DATA / "tiny.lua", tmp_path / "tiny.lua")
    (tmp_path / "loop.lua").write_text("function post_experiment()\n" + post_experiment + "\nend\n")
    argos = (DATA / "tiny_loop.argos").read_text().replace('script="tiny_loop.lua"', 'script="loop.lua"')
    (tmp_path / "x.argos").write_text(argos)
    r = run("run", tmp_path / "x.argos", "--out", tmp_path / "o", "--ticks", 2, cwd=tmp_path)
    assert r.returncode == 0, r.stderr
    return r, (tmp_path / "o" / "metrics.json").read_text()


def test_nan_metric_is_null_with_one_warning(tmp_path):
    r, text = _loop_experiment(tmp_path, "return {ok = 1.5, bad = 0/0, deep = {inf = math.huge, list = {1, -math.huge}}}")
    assert json.loads(text) == {"bad": None, "deep": {"inf": None, "list": [1, None]}, "ok": 1.5}
    warnings = [line for line in r.stderr.splitlines() if "NaN or infinite" in line]
    assert len(warnings) == 1
    assert "bad, deep.inf, deep.list[2]" in warnings[0]


def test_keys_and_strings_with_nul_are_written_whole(tmp_path):
    _, text = _loop_experiment(tmp_path, 'return {["a\\0b"] = "x\\0y", a = 1}')
    assert json.loads(text) == {"a": 1, "a\0b": "x\0y"}
    assert "\\u0000" in text


def test_numbers_round_trip(tmp_path):
    _, text = _loop_experiment(tmp_path, "return {third = 1/3, big = 1e300, tiny = 5e-324, int = 9007199254740993}")
    data = json.loads(text)
    assert data == {"big": 1e300, "int": 9007199254740993, "third": 1 / 3, "tiny": 5e-324}


@pytest.mark.parametrize("words, expected", [
    (["essaim", "ch"], ["check"]),
    (["essaim", "run", "--ti"], ["--ticks"]),
    (["essaim", "snapshot", "--s"], ["--size"]),
    (["essaim", "help", "sn"], ["snapshot"]),
])
def test_bash_completion_from_the_option_definitions(words, expected):
    script = run("completion", "bash").stdout
    cmd = f'{script}\nCOMP_WORDS=({" ".join(words)}); COMP_CWORD={len(words) - 1}; _essaim; echo "${{COMPREPLY[@]}}"'
    r = subprocess.run(["bash", "-c", cmd], capture_output=True, text=True, timeout=30)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == expected
