#!/usr/bin/env python3
"""The clustering experiment's loop functions in C++ (tests/argos/clustering_cpp) against
their Lua twin (arenas/clustering_loop.lua): seconds in the loop-function stages per tick
(summary.json's stage_seconds.loop_functions / ticks), the least of runs alternated between
the two, at the file's 12 cylinders and at 48. Builds the C++ project against the build
tree first.

    .venv/bin/python bench/loop_functions_cpp_vs_lua.py [--essaim build/essaim] [--runs 7]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "argos"))


def loop_seconds_per_tick(essaim, argos, extra, out):
    subprocess.run([essaim, "run", str(argos), "--out", str(out), "--ticks", "800", *extra], check=True,
                   capture_output=True, text=True)
    summary = json.loads((out / "summary.json").read_text())
    return summary["stage_seconds"]["loop_functions"] / summary["ticks"], summary["ticks"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--essaim", default=str(ROOT / "build" / "essaim"))
    parser.add_argument("--runs", type=int, default=7)
    args = parser.parse_args()
    os.environ["ESSAIM"] = str(Path(args.essaim).resolve())
    import argos_projects  # noqa: E402 (reads ESSAIM)

    folder = Path(tempfile.mkdtemp(prefix="essaim-bench-lf-"))
    project = argos_projects.build_project(ROOT / "tests" / "argos" / "clustering_cpp", folder)
    library = project / "build" / "libclustering_loop_functions.so"
    cpp_argos = ROOT / "tests" / "argos" / "clustering_cpp" / "clustering_cpp.argos"
    lua_argos = ROOT / "arenas" / "clustering.argos"
    print("cylinders  ticks  Lua us/tick  C++ us/tick  C++/Lua")
    for count in (12, 48, 120):
        times = {"lua": [], "cpp": []}
        for run in range(args.runs):
            out = folder / f"lua-{count}-{run}"
            lua, ticks = loop_seconds_per_tick(args.essaim, lua_argos, ["--set", f"loop_functions.cylinders.count={count}"],
                                               out)
            out = folder / f"cpp-{count}-{run}"
            cpp, _ = loop_seconds_per_tick(args.essaim, cpp_argos, [
                "--set", f"loop_functions.library={library}", "--set", f"loop_functions.output.dir={out}",
                "--set", f"loop_functions.cylinders.count={count}"], out)
            times["lua"].append(lua)
            times["cpp"].append(cpp)
        lua, cpp = min(times["lua"]) * 1e6, min(times["cpp"]) * 1e6
        print(f"{count:9d}  {ticks:5d}  {lua:11.1f}  {cpp:11.1f}  {cpp / lua:7.2f}")


if __name__ == "__main__":
    main()
