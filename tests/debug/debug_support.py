"""What the tests of `essaim debug` share: a copy of the shipped foraging experiment in the
test's folder (so that a test may add a log() line or an error to its controller), the lines
of the controller the tests stop at, `essaim run` for the expected values, and the reader of
recording.bin (docs/recording.md)."""
from __future__ import annotations

import json
import shutil
import struct
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

# 5 of the 30 robots, 40 ticks: a session takes well under a second.
ROBOTS = 5
SHORT = ["--ticks", "40", "--seed", "3", "--set", f"arena.distribute.entity.quantity={ROBOTS}"]
# What differs between two runs of the same experiment and seed: times, and the Lua heap
# (evaluating expressions in a session allocates in the robots' states); and the debug section.
VARYING_SUMMARY_KEYS = ("wall_seconds", "robot_steps_per_second", "us_per_robot_step", "stage_seconds",
                        "setup_seconds", "lua_memory_bytes", "debug")


def foraging_copy(folder: Path) -> Path:
    """arenas/foraging.argos with its loop functions and controllers/, copied into `folder`
    (the experiment finds ../controllers/foraging.lua as in the checkout); returns the .argos."""
    (folder / "arenas").mkdir(parents=True, exist_ok=True)
    for name in ("foraging.argos", "foraging_loop.lua"):
        shutil.copy(ROOT / "arenas" / name, folder / "arenas" / name)
    shutil.copytree(ROOT / "controllers", folder / "controllers", dirs_exist_ok=True)
    return folder / "arenas" / "foraging.argos"


def controller(argos: Path) -> Path:
    return (argos.parent / ".." / "controllers" / "foraging.lua").resolve()


def line_of(path: Path, text: str) -> int:
    """The number of the first line of `path` that contains `text`."""
    for n, line in enumerate(path.read_text().splitlines(), 1):
        if text in line:
            return n
    raise AssertionError(f"{path} has no line with {text!r}")


def insert_after(path: Path, text: str, new: str) -> int:
    """Adds the line `new` after the first line containing `text`; returns its number."""
    lines = path.read_text().splitlines()
    n = line_of(path, text)
    lines.insert(n, new)
    path.write_text("\n".join(lines) + "\n")
    return n + 1


# foraging.lua's step(): the tests stop on these lines.
FIRST = "tick = tick + 1"                              # step()'s first line
ACTIONS = "local actions = behaviour.step("           # the tick counter is the world's tick here
WHEELS = "robot.wheels.set_velocity(actions.left"      # actions computed

# A log() line for the expected values: the robot, the tick, the wheel speeds and the 24
# proximity readings, every number exact (%.17g).
LOG_LINE = ('log(string.format("DBG %s %d %.17g %.17g", robot.id, tick, actions.left, actions.right)'
            ' .. (function() local s = "" for i = 1, #robot.proximity do'
            ' s = s .. string.format(" %.17g/%.17g", robot.proximity[i].value, robot.proximity[i].angle)'
            ' end return s end)())')


def add_log_line(argos: Path) -> int:
    """Puts LOG_LINE after the wheels line of the copy's foraging.lua; returns its line."""
    return insert_after(controller(argos), WHEELS, "  " + LOG_LINE)


def logged(stdout: str) -> dict:
    """(robot id, tick) -> {"left", "right", "proximity": [(value, angle)...]} from LOG_LINE's lines."""
    found = {}
    for line in stdout.splitlines():
        words = line.split()
        if len(words) < 5 or words[0] != "DBG":
            continue
        prox = [tuple(float(x) for x in w.split("/")) for w in words[5:]]
        found[(words[1], int(words[2]))] = {"left": float(words[3]), "right": float(words[4]),
                                            "proximity": prox}
    return found


def essaim_run(essaim: str, argos: Path, args, out: Path, cwd: Path):
    """`essaim run` as the expected result; returns (CompletedProcess, summary.json)."""
    r = subprocess.run([essaim, "run", str(argos), *map(str, args), "--quiet", "--out", str(out)],
                       cwd=cwd, capture_output=True, text=True, timeout=120)
    summary = out / "summary.json"
    return r, (json.loads(summary.read_text()) if summary.exists() else None)


def summary(out: Path) -> dict:
    return json.loads((out / "summary.json").read_text())


def comparable(s: dict) -> dict:
    """A summary less what differs between two runs of the same experiment and seed."""
    return {k: v for k, v in s.items() if k not in VARYING_SUMMARY_KEYS}


def recording(path: Path):
    """recording.bin read as docs/recording.md lays it out: (robot ids, {tick: [(x, y, yaw)...]})."""
    b = path.read_bytes()
    H, F = struct.unpack_from("<II", b, 12)
    nrob = struct.unpack_from("<I", b, 32)[0]
    minx, miny, sx, sy, u = struct.unpack_from("<5d", b, 56)
    cx, cy = minx + sx / 2, miny + sy / 2
    off = 104
    n = struct.unpack_from("<H", b, off)[0]
    off += 2 + n
    ids = []
    for _ in range(nrob):
        n = struct.unpack_from("<H", b, off)[0]
        ids.append(b[off + 2:off + 2 + n].decode())
        off += 2 + n
    frames = {}
    for k in range((len(b) - H) // F):
        base = H + k * F
        tick = struct.unpack_from("<I", b, base)[0]
        poses = []
        for i in range(nrob):
            x, y, yaw = struct.unpack_from("<hhH", b, base + 4 + 10 * i)
            poses.append((cx + x * u, cy + y * u, yaw * 2 * 3.141592653589793 / 65536))
        frames[tick] = poses
    return ids, frames, u
