"""The editors' configurations of `essaim debug`. The VS Code extension of tools/vscode-essaim:
its package.json is what VS Code requires of an extension that contributes a debugger, and
the launch configurations it offers (and the sample .vscode/launch.json) start a real
session, run the way VS Code runs them: the adapter command from the manifest, the
configuration as the launch arguments. docs/debugging.md's nvim-dap snippet, run by Lua with
a stand-in for nvim-dap's module, gives adapters and a configuration that start real
sessions too (over stdio and over --port); its launch.json is the manifest's."""
import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from dap_client import DapClient, free_port
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
    return run_session(dap, config, folder)


def run_session(dap: DapClient, config: dict, folder: Path) -> Path:
    """Launches `config` as an editor does and runs it to its end; returns its --out folder."""
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


DOC = ROOT / "docs" / "debugging.md"
LUA_JSON = r"""
local function encode(v)
  if type(v) == "table" then
    local parts = {}
    if #v > 0 then
      for _, x in ipairs(v) do parts[#parts + 1] = encode(x) end
      return "[" .. table.concat(parts, ",") .. "]"
    end
    for k, x in pairs(v) do parts[#parts + 1] = encode(tostring(k)) .. ":" .. encode(x) end
    return "{" .. table.concat(parts, ",") .. "}"
  elseif type(v) == "string" then
    return '"' .. v:gsub('[%c"\\]', function(c) return string.format("\\u%04x", c:byte()) end) .. '"'
  end
  return tostring(v)
end
local dap = { adapters = {}, configurations = {} }
package.preload.dap = function() return dap end
dofile(arg[1])
print(encode(dap))
"""


def doc_block(lang: str) -> str:
    """The first ```lang block of docs/debugging.md."""
    m = re.search(rf"^```{lang}\n(.*?)^```", DOC.read_text(), re.S | re.M)
    assert m, f"docs/debugging.md has no {lang} block"
    return m.group(1)


def nvim_dap(tmp_path: Path) -> dict:
    """What the doc's nvim-dap snippet leaves in require("dap"), run by Lua 5.4."""
    lua = shutil.which("lua5.4") or shutil.which("lua")
    if not lua:
        pytest.skip("no lua interpreter on PATH to run the nvim-dap snippet")
    (tmp_path / "snippet.lua").write_text(doc_block("lua"))
    (tmp_path / "run.lua").write_text(LUA_JSON)
    r = subprocess.run([lua, "run.lua", "snippet.lua"], cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def test_the_docs_launch_json_is_the_manifests_initial_configuration():
    assert json.loads(doc_block("json"))["configurations"] == debugger()["initialConfigurations"]


@pytest.mark.parametrize("adapter", ["essaim", "essaim_tcp"])
def test_the_docs_nvim_dap_snippet_starts_sessions(essaim, tmp_path, adapter):
    dap_module = nvim_dap(tmp_path)
    [config] = dap_module["configurations"]["lua"]
    assert config["type"] == "essaim" and set(config) - VSCODE_KEYS <= LAUNCH_ATTRIBUTES
    spec = dap_module["adapters"][adapter]
    folder = workspace(tmp_path / "ws")
    if spec["type"] == "executable":
        assert spec["command"] == "essaim"
        dap = DapClient.command([essaim, *spec["args"]], cwd=folder)
    else:  # nvim-dap picks a free port for "${port}", starts the executable, connects
        assert spec["type"] == "server" and spec["port"] == "${port}"
        assert spec["executable"]["command"] == "essaim"
        port = str(free_port())
        argv = [essaim, *(port if a == "${port}" else a for a in spec["executable"]["args"])]
        dap = DapClient.server(argv, int(port), cwd=folder)
    out = run_session(dap, as_vscode_sends(config, folder), folder)
    assert json.loads((out / "summary.json").read_text())["ticks"] == 20
