#!/usr/bin/env python3
"""Foot-bot trajectories of essaim against those ARGoS 3 printed for the same scenes.

The scenes and ARGoS's output come from tests/data/motion/argos-m1.tar.xz (measured in ARGoS 3,
see tests/data/motion/README.md): each scene's robots follow fixed wheel scripts (motion.lua)
and print `POSE <tick> <id> x y yaw` every tick. This module extracts the archive, runs essaim
on every scene from the scene's folder as ARGoS was run, and measures each robot's position
error against ARGoS's, grouped by the scene's class (free, wall, robot, push).

The box pushes (argos-m4.tar.xz, kept beside the project in ../shared/motion, not in it: 48
scenes of robots pushing movable boxes, class "box", besides 60 scenes like m1's) carry their
own motion.lua and objlog.lua, and print `OBJ <tick> <id> x y yaw` for each movable object:
those are measured too, as rows of body "object" (robots' rows are body "robot").

usage: motion_compare.py ESSAIM [--archive A] [--jobs N] [--ticks T] [--per-robot]
prints the table of docs/compatibility.md's motion section.
"""
import argparse
import concurrent.futures
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

DATA = Path(__file__).resolve().parents[1] / "data" / "motion"
ARCHIVE = DATA / "argos-m1.tar.xz"
# Beside the project's checkout (../shared/motion), or where ESSAIM_MOTION_M4 says.
BOX_ARCHIVE = Path(os.environ.get("ESSAIM_MOTION_M4",
                                  Path(__file__).resolve().parents[3] / "shared" / "motion" / "argos-m4.tar.xz"))
CONTROLLER = DATA / "motion.lua"
CLASSES = ["free", "wall", "robot", "push", "box"]
POSE = re.compile(r"POSE (\d+) (\S+) (\S+) (\S+) (\S+)")
OBJ = re.compile(r"OBJ (\d+) (\S+) (\S+) (\S+) (\S+)")


def extract(archive: Path, dest: Path) -> list:
    """The archive's scenes extracted into dest, with the controller their files name."""
    with tarfile.open(archive) as tar:
        tar.extractall(dest)
    if not (dest / "motion.lua").exists():  # m1 came without it; m4 has its own scripts
        shutil.copy(CONTROLLER, dest / "motion.lua")
    return (dest / "index.txt").read_text().split()


def poses(text: str, pattern=POSE) -> dict:
    """{(tick, id): (x, y, yaw)} from the POSE (robots) or OBJ (objects) lines of a run's output."""
    found = {}
    for m in pattern.finditer(text):
        found[(int(m.group(1)), m.group(2))] = tuple(float(v) for v in m.group(3, 4, 5))
    return found


def run_scene(essaim: str, scene: Path, ticks: int, extra=()) -> dict:
    """essaim's poses on one scene; a failed run raises with its output."""
    out = scene / "essaim_run"
    shutil.rmtree(out, ignore_errors=True)
    cmd = [essaim, "run", "exp.argos", "--ticks", str(ticks), "--out", str(out), *extra]
    proc = subprocess.run(cmd, cwd=scene, capture_output=True, text=True, timeout=300)
    if proc.returncode != 0:
        raise RuntimeError(f"{scene.name}: {' '.join(cmd)} exited {proc.returncode}\n{proc.stderr[-2000:]}")
    text = proc.stdout + proc.stderr
    return {"robot": poses(text), "object": poses(text, OBJ)}


def scene_errors(scene: Path, ours: dict, tick: int) -> list:
    """One row per robot and movable object of the scene: its class, body ("robot" or
    "object"), id and position error at `tick` (m)."""
    meta = json.loads((scene / "meta.json").read_text())
    text = (scene / "argos.out").read_text()
    theirs = {"robot": poses(text), "object": poses(text, OBJ)}
    rows = []
    for body, ids in (("robot", meta["ids"]), ("object", meta.get("objects", []))):
        for rid in ids:
            a, e = theirs[body].get((tick, rid)), ours[body].get((tick, rid))
            if a is None or e is None:
                raise RuntimeError(f"{scene.name}: {body} {rid} printed no pose at tick {tick}")
            rows.append({"scene": scene.name, "robot": rid, "cls": meta["cls_ideal"], "body": body,
                         "error": math.hypot(a[0] - e[0], a[1] - e[1])})
    return rows


def compare(essaim: str, archive: Path = ARCHIVE, ticks: int = 300, jobs: int = 2, extra=(), only=None) -> list:
    """Every robot's and object's error at the last tick, all scenes of the archive (or those
    whose meta.json's class is in `only`) run by essaim."""
    essaim = str(Path(essaim).resolve())  # each scene runs from its own folder
    with tempfile.TemporaryDirectory(prefix="essaim-motion-") as tmp:
        scenes = [Path(tmp) / name for name in extract(archive, Path(tmp))]
        if only is not None:
            scenes = [s for s in scenes if json.loads((s / "meta.json").read_text())["cls_ideal"] in only]
        with concurrent.futures.ThreadPoolExecutor(jobs) as pool:
            runs = list(pool.map(lambda s: run_scene(essaim, s, ticks, extra), scenes))
        return [row for s, ours in zip(scenes, runs) for row in scene_errors(s, ours, ticks)]


def summarise(rows: list, body: str = "robot") -> dict:
    """Per class, over the rows of `body`: how many, median and max error (m), shares within
    1 mm and 1 cm."""
    table = {}
    for cls in CLASSES:
        errors = sorted(r["error"] for r in rows if r["cls"] == cls and r.get("body", "robot") == body)
        if not errors:
            continue
        table[cls] = {"robots": len(errors), "median": statistics.median(errors), "max": errors[-1],
                      "within_1mm": sum(e <= 1e-3 for e in errors) / len(errors),
                      "within_1cm": sum(e <= 1e-2 for e in errors) / len(errors)}
    return table


def markdown(table: dict, body: str = "robot") -> str:
    lines = [f"| class | {body}s | median error @300 | max @300 | within 1 mm | within 1 cm |",
             "|---|---|---|---|---|---|"]
    for cls, t in table.items():
        lines.append(f"| {cls} | {t['robots']} | {t['median'] * 1e3:.3f} mm | {t['max'] * 1e3:.3f} mm "
                     f"| {t['within_1mm']:.0%} | {t['within_1cm']:.0%} |")
    return "\n".join(lines)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("essaim")
    ap.add_argument("--archive", type=Path, default=ARCHIVE)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--ticks", type=int, default=300)
    ap.add_argument("--only", nargs="+", choices=CLASSES, help="only the scenes of these classes")
    ap.add_argument("--per-robot", action="store_true", help="also list every robot's and object's error")
    args = ap.parse_args()
    rows = compare(args.essaim, args.archive, args.ticks, args.jobs, only=args.only)
    if args.per_robot:
        for r in sorted(rows, key=lambda r: (r["cls"], r["body"], -r["error"])):
            print(f"{r['cls']:6} {r['body']:6} {r['scene']} {r['robot']:6} {r['error'] * 1e3:10.4f} mm")
    print(markdown(summarise(rows)))
    if any(r["body"] == "object" for r in rows):
        print(markdown(summarise(rows, "object"), "object"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
