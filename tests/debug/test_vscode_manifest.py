"""The VS Code extension of tools/vscode-essaim: its package.json is what VS Code requires of
an extension that contributes a debugger, and the launch configurations it offers (and the
sample .vscode/launch.json) start a real `essaim debug` session, run the way VS Code runs
them: the adapter command from the manifest, the configuration as the launch arguments."""
import json
import re
import shutil
from pathlib import Path

import pytest

from dap_client import DapClient
from debug_support import ROOT

EXT = ROOT / "tools" / "vscode-essaim"
LAUNCH_ATTRIBUTES = {"experiment", "args", "cwd", "stopOnEntry"}  # docs/debugging.md
VSCODE_KEYS = {"type", "request", "name"}  # every configuration has them; VS Code adds more


def manifest() -> dict:
    return json.loads((EXT / "package.json").read_text())


def debugger() -> dict:
    [d] = manifest()["contributes"]["debuggers"]
    return d


def jsonc(path: Path):
    """launch.json is JSON with comments (VS Code's "JSONC"): whole-line // comments here."""
    text = "\n".join(line for line in path.read_text().splitlines() if not line.lstrip().startswith("//"))
    return json.loads(text)


def test_the_manifest_has_what_vscode_requires_of_a_debugger_extension():
    m = manifest()
    for key in ("name", "version", "publisher", "engines", "displayName", "description"):
        assert m.get(key), key
    assert re.fullmatch(r"[a-z0-9][a-z0-9.-]*", m["name"])  # lower case, no spaces
    assert re.fullmatch(r"\d+\.\d+\.\d+", m["version"])
    assert m["engines"]["vscode"].startswith("^1.")
    assert "Debuggers" in m["categories"]
    assert {"language": "lua"} in m["contributes"]["breakpoints"]
    d = debugger()
    assert d["type"] == "essaim" and d["label"]
    # the adapter: the essaim executable on PATH, started as `essaim debug`
    assert d["runtime"] == "essaim" and d["runtimeArgs"] == ["debug"] and "program" not in d
    launch = d["configurationAttributes"]["launch"]
    assert set(launch["properties"]) == LAUNCH_ATTRIBUTES
    assert set(launch["required"]) <= LAUNCH_ATTRIBUTES
    types = {k: v["type"] for k, v in launch["properties"].items()}
    assert types == {"experiment": "string", "args": "array", "cwd": "string", "stopOnEntry": "boolean"}
    for name, prop in launch["properties"].items():
        assert prop["description"], name
    for config in d["initialConfigurations"] + [s["body"] for s in d["configurationSnippets"]]:
        assert config["type"] == "essaim" and config["request"] == "launch" and config["name"]
        assert set(config) - VSCODE_KEYS <= LAUNCH_ATTRIBUTES
        assert set(launch["required"]) <= set(config)


def test_the_sample_launch_json_uses_only_the_manifests_attributes():
    sample = jsonc(EXT / ".vscode" / "launch.json")
    assert sample["version"] == "0.2.0" and sample["configurations"]
    for config in sample["configurations"]:
        assert config["type"] == "essaim" and config["request"] == "launch" and config["name"]
        assert set(config) - VSCODE_KEYS <= LAUNCH_ATTRIBUTES


def workspace(tmp_path: Path) -> Path:
    """A folder as a user's workspace: the checkout's arenas/ and controllers/."""
    for d in ("arenas", "controllers"):
        shutil.copytree(ROOT / d, tmp_path / d)
    return tmp_path


def as_vscode_sends(config: dict, folder: Path) -> dict:
    """The configuration as VS Code sends it in `launch`: ${workspaceFolder} substituted, a
    session id added; the run shortened for the test (--ticks 20, 5 robots)."""
    text = json.dumps(config).replace("${workspaceFolder}", str(folder))
    config = json.loads(text)
    args = list(config.get("args", []))
    if "--ticks" in args:
        args[args.index("--ticks") + 1] = "20"
    args += ["--set", "arena.distribute.entity.quantity=5"] if not any("quantity" in a for a in args) else []
    config["args"] = args
    config["__sessionId"] = "0f8a2b7c-test"
    return config


def run_like_vscode(essaim: str, config: dict, folder: Path) -> Path:
    """Starts the adapter as the manifest says, launches `config`, runs it to its end;
    returns the run folder (its --out)."""
    dap = DapClient.command([essaim, *debugger()["runtimeArgs"]], cwd=folder)  # runtime "essaim": ours
    try:
        dap.request("initialize", {"clientID": "vscode", "clientName": "Visual Studio Code", "adapterID": "essaim",
                                   "pathFormat": "path", "linesStartAt1": True, "columnsStartAt1": True,
                                   "supportsVariableType": True, "supportsRunInTerminalRequest": True})
        seq = dap.send("launch", config)
        dap.wait_event("initialized")
        dap.request("setExceptionBreakpoints", {"filters": []})
        dap.request("configurationDone")
        assert dap.response(seq)["success"]
        if config.get("stopOnEntry"):
            stop = dap.stopped()
            assert stop["reason"] == "entry"
            dap.request("continue", {"threadId": stop["threadId"]})
        assert dap.finish() == 0
    finally:
        dap.kill()
    args = config["args"]
    out = Path(args[args.index("--out") + 1])
    return out if out.is_absolute() else Path(config.get("cwd", folder)) / out


@pytest.mark.parametrize("source", ["initialConfigurations", "launch.json"])
def test_the_offered_configurations_run_a_session(essaim, tmp_path, source):
    folder = workspace(tmp_path)
    configs = (debugger()["initialConfigurations"] if source == "initialConfigurations"
               else jsonc(EXT / ".vscode" / "launch.json")["configurations"])
    for config in configs:
        out = run_like_vscode(essaim, as_vscode_sends(config, folder), folder)
        s = json.loads((out / "summary.json").read_text())
        assert s["status"] == "ok" and s["ticks"] == 20 and s["robots"] == 5
        assert s["debug"] == {"divergences": []}
