"""Every sensor reading equals ARGoS's, on the scenes measured in ARGoS 3 itself.

tests/data/fidelity holds what ARGoS 3 (421bd763, dynamics2d, double precision) printed for
484 still probe scenes (argos-s1: 150 random and 34 hand-made, argos-s2: 300 random), and
probe.lua, the controller both simulators run: on ticks 1-3 it prints one line per reading,
`PROBE <tick> <robot> <sensor> <index> <field>=<value> ...`, and `<sensor>_n` lines with each
table's length. Each archive is extracted into a temporary folder and essaim runs every scene
from its folder, as ARGoS was run. A scene fails on any reading more than 1e-3 from ARGoS's,
any reading one simulator gives and the other does not, any table of another length, and
any run that does not end with exit code 0.

Readings are matched by their index (positioning, proximity, light, ground, the scanner's
tables, which probe.lua sorts by angle, so a ray reported at -pi instead of +pi moves), by the
sender's bytes (range and bearing) and by the blob's colour (camera; probe.lua gives every LED
its own). Angles are compared modulo 2 pi.

Run as a script to print the per-sensor table (docs/compatibility.md) for these archives or
for others of the same generator:
    ESSAIM=build/essaim python tests/fidelity/argos_test.py [ARCHIVE.tar.xz ...]
"""
import collections
import concurrent.futures
import math
import os
import shutil
import subprocess
import sys
import tarfile
from pathlib import Path

import pytest

DATA = Path(__file__).resolve().parents[1] / "data" / "fidelity"
ARCHIVES = ("argos-s1.tar.xz", "argos-s2.tar.xz")
ESSAIM = os.path.abspath(os.environ["ESSAIM"]) if os.environ.get("ESSAIM") else None
TOLERANCE = 1e-3
ANGLE_FIELDS = {"angle", "hbearing", "vbearing", "yaw"}
TEXT_FIELDS = {"data", "color"}
SENSORS = ("pos", "prox", "light", "mground", "bground", "scan_short_range", "scan_long_range", "rab", "blob")
# Scenes run at once: each is a few tens of milliseconds of one core.
WORKERS = 3


def parse(text):
    """PROBE lines into ({(tick, robot, sensor, key): fields}, {(tick, robot, sensor): n})."""
    readings, counts = {}, {}
    for line in text.splitlines():
        if not line.startswith("PROBE "):
            continue
        parts = line.split(" ")
        tick, robot, sensor, index = int(parts[1]), parts[2], parts[3], parts[4]
        fields = dict(kv.split("=", 1) for kv in parts[5:])
        if sensor.endswith("_n"):
            counts[(tick, robot, sensor[:-2])] = int(fields["n"])
            continue
        key = fields["data"] if sensor == "rab" else fields["color"] if sensor == "blob" else index
        base = (tick, robot, sensor, key)
        key, copy = base, 1
        while key in readings:  # two LEDs of one colour: matched in their sorted order
            copy += 1
            key = base[:3] + (f"{base[3]}#{copy}",)
        readings[key] = fields
    return readings, counts


def field_difference(name, a, b):
    if name in TEXT_FIELDS:
        return 0.0 if a == b else math.inf
    d = float(a) - float(b)
    if name in ANGLE_FIELDS:
        d = (d + math.pi) % (2 * math.pi) - math.pi
    return abs(d) if not math.isnan(d) else math.inf


def compare(argos_text, essaim_text, stats=None):
    """The problems of one scene, each a line; `stats` (per sensor counters) is filled."""
    ra, ca = parse(argos_text)
    re_, ce = parse(essaim_text)
    problems = []
    if not ra:
        problems.append("ARGoS printed no readings")
    if not re_:
        problems.append("essaim printed no readings")
    for key in sorted(set(ca) | set(ce), key=str):
        if ca.get(key) != ce.get(key):
            problems.append(f"t={key[0]} {key[1]} {key[2]}: ARGoS has {ca.get(key)} readings, essaim {ce.get(key)}")
    for key in sorted(set(ra) | set(re_), key=str):
        sensor = key[2]
        st = stats[sensor] if stats is not None else collections.Counter()
        if key not in re_ or key not in ra:
            st["only_argos" if key in ra else "only_essaim"] += 1
            which = "ARGoS" if key in ra else "essaim"
            problems.append(f"t={key[0]} {key[1]} {sensor} #{key[3]}: only in {which}: {(ra.get(key) or re_[key])}")
            continue
        fa, fe = ra[key], re_[key]
        worst = max(field_difference(f, fa.get(f), fe.get(f)) if f in fa and f in fe else math.inf
                    for f in set(fa) | set(fe))
        st["compared"] += 1
        st["within_1e-6"] += worst <= 1e-6
        st["within_1e-3"] += worst <= TOLERANCE
        st["largest"] = max(st["largest"], worst)
        if worst > TOLERANCE:
            problems.append(f"t={key[0]} {key[1]} {sensor} #{key[3]}: ARGoS {fa} essaim {fe}")
    return problems


def extract(archive, folder):
    """The archive's scenes in `folder`, probe.lua beside them; the scene names in order."""
    with tarfile.open(archive) as tar:
        tar.extractall(folder)
    shutil.copy(DATA / "probe.lua", folder / "probe.lua")
    return [line.strip() for line in (folder / "index.txt").read_text().splitlines() if line.strip()]


def run_scene(scene):
    """essaim on one scene as ARGoS was run (from its folder); the problems of the run."""
    r = subprocess.run([ESSAIM, "run", "exp.argos", "--out", "essaim_run"], cwd=scene, capture_output=True,
                       text=True, timeout=120)
    argos_rc = (scene / "argos.rc").read_text().strip()
    problems = [] if r.returncode == 0 else [f"essaim exit code {r.returncode}: {r.stderr.strip()[-300:]}"]
    if argos_rc != "0":
        problems.append(f"ARGoS exit code {argos_rc}")
    return (scene / "argos.out").read_text(errors="replace"), r.stdout, problems


def check_archive(archive, folder, stats):
    """Every problem of every scene of the archive, each line prefixed with its scene."""
    names = extract(archive, folder)
    problems = []
    with concurrent.futures.ThreadPoolExecutor(WORKERS) as pool:
        for name, (argos_out, essaim_out, run_problems) in zip(names, pool.map(run_scene, [folder / n for n in names])):
            for p in run_problems + compare(argos_out, essaim_out, stats):
                problems.append(f"{Path(archive).name} {name}: {p}")
    return len(names), problems


def new_stats():
    return collections.defaultdict(lambda: collections.Counter(largest=0.0))


need_essaim = pytest.mark.skipif(not ESSAIM, reason="ESSAIM (the essaim binary) is not set")


@need_essaim
@pytest.mark.parametrize("archive", ARCHIVES)
def test_every_reading_equals_argos(archive, tmp_path):
    scenes, problems = check_archive(DATA / archive, tmp_path, new_stats())
    assert scenes > 0
    assert not problems, f"{len(problems)} readings differ from ARGoS's:\n" + "\n".join(problems[:40])


def probe_lines():
    """One scene's ARGoS output, to check that the comparison catches what it must."""
    with tarfile.open(DATA / ARCHIVES[0]) as tar:
        member = next(m for m in tar.getmembers() if m.name.endswith("argos.out"))
        return tar.extractfile(member).read().decode()


def test_a_reading_off_by_more_than_the_tolerance_fails():
    text = probe_lines()
    line = next(l for l in text.splitlines() if " prox " in l)
    value = line.split("value=")[1].split(" ")[0]
    moved = line.replace(f"value={value}", f"value={float(value) + 2 * TOLERANCE:.9g}")
    assert compare(text, text) == []
    problems = compare(text, text.replace(line, moved))
    assert len(problems) == 1 and " prox " in problems[0]
    assert compare(text, text.replace(line, line.replace(f"value={value}", f"value={float(value) + TOLERANCE / 2:.9g}"))) == []


def test_a_missing_reading_and_a_table_of_another_length_fail():
    text = probe_lines()
    line = next(l for l in text.splitlines() if " prox " in l)
    count = next(l for l in text.splitlines() if " prox_n " in l)
    problems = compare(text, text.replace(line + "\n", "").replace(count, count.replace("n=24", "n=23")))
    assert any("only in ARGoS" in p for p in problems)
    assert any("ARGoS has 24 readings, essaim 23" in p for p in problems)


def test_angles_compare_modulo_a_turn_and_the_scanner_by_position():
    a = "PROBE 1 fb0 rab 1 range=10 hbearing=3.14159 vbearing=0 data=1,2\n"
    assert compare(a, a.replace("hbearing=3.14159", "hbearing=-3.14159")) == []
    s = ("PROBE 1 fb0 scan_long_range 1 angle=-3.14159265 distance=-2\n"
         "PROBE 1 fb0 scan_long_range 2 angle=0 distance=50\n")
    flipped = ("PROBE 1 fb0 scan_long_range 1 angle=0 distance=50\n"
               "PROBE 1 fb0 scan_long_range 2 angle=3.14159265 distance=-2\n")
    assert len(compare(s, flipped)) == 2  # a ray at +pi sorts last, where ARGoS's -pi sorts first


def print_table(archives):
    """The per-sensor table of docs/compatibility.md, and every problem, for these archives."""
    import tempfile
    stats, scenes, problems = new_stats(), 0, []
    for archive in archives:
        with tempfile.TemporaryDirectory() as folder:
            n, p = check_archive(Path(archive), Path(folder), stats)
            scenes, problems = scenes + n, problems + p
    print(f"{scenes} scenes from {', '.join(Path(a).name for a in archives)}\n")
    print("| sensor | readings | within 1e-6 | within 1e-3 | largest difference | only in ARGoS | only in essaim |")
    print("|---|---|---|---|---|---|---|")
    for s in SENSORS:
        st = stats[s]
        print(f"| {s} | {st['compared']} | {st['within_1e-6']} | {st['within_1e-3']} | {st['largest']:.3g} | "
              f"{st['only_argos']} | {st['only_essaim']} |")
    count_problems = sum("readings, essaim" in p for p in problems)
    print(f"\ntables of another length: {count_problems}; problems in all: {len(problems)}")
    for p in problems[:60]:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    if not ESSAIM:
        sys.exit("set ESSAIM to the essaim binary")
    sys.exit(print_table(sys.argv[1:] or [DATA / a for a in ARCHIVES]))
