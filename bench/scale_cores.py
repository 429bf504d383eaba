#!/usr/bin/env python3
"""How the scaled avoidance swarm's step divides over cores: physics regions × threads.

Runs `essaim run` on bench/avoidance_1000.argos grown to each size at constant density (the
scaling `essaim bench scale` uses), once per (regions, threads) pair, and prints, from each
run's summary.json, µs per robot-step, the real-time factor and the stage seconds per tick.
Physics is timed as wall seconds (its regions step on the pool); sense and control are summed
over threads. `--project` fits the single-thread runs and projects the real-time factor to
more cores (docs/scale.md explains the model).

  python3 bench/scale_cores.py --sizes 10000 --threads 1,2,4,8,16 --regions 1,same
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile


def scale_overrides(robots):
    """The --set values of src/app/bench_scale.cpp's ScaleOverrides, as a JSON object."""
    s = math.sqrt(robots / 1000.0)
    side, wall, half = f"{32 * s:.6g}", f"{16 * s:.6g}", f"{15 * s:.6g}"
    obstacles = max(1, robots // 10)
    o = {
        "framework.system.max_entities": robots + 2 * obstacles + 4,
        "arena.size": f"{side},{side},1",
        "arena.wall_north.size": f"{side},0.1,0.5",
        "arena.wall_south.size": f"{side},0.1,0.5",
        "arena.wall_east.size": f"0.1,{side},0.5",
        "arena.wall_west.size": f"0.1,{side},0.5",
        "arena.wall_north.body.position": f"0,{wall},0",
        "arena.wall_south.body.position": f"0,-{wall},0",
        "arena.wall_east.body.position": f"{wall},0,0",
        "arena.wall_west.body.position": f"-{wall},0,0",
    }
    for d in range(3):
        at = f"arena.distribute[{d}]."
        o[at + "position.min"] = f"-{half},-{half},0"
        o[at + "position.max"] = f"{half},{half},0"
        o[at + "entity.quantity"] = robots if d == 2 else obstacles
    return o


def run_once(args, robots, regions, threads, work):
    """One run; returns its summary.json as a dict."""
    set_file = os.path.join(work, f"set-{robots}.json")
    with open(set_file, "w") as f:
        json.dump(scale_overrides(robots), f)
    out = os.path.join(work, f"r{robots}-k{regions}-t{threads}")
    cmd = [args.essaim, "run", os.path.join(args.dir, "avoidance_1000.argos"), "-q",
           "--ticks", str(args.ticks), "--threads", str(threads), "--set-file", set_file,
           "--set", f"physics_engines.dynamics2d.regions={regions}", "-o", out]
    subprocess.run(cmd, check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def row(s, regions):
    """The figures one run contributes, per tick."""
    ticks, stages = s["ticks"], s["stage_seconds"]
    setup = s["setup_seconds"]
    # wall_seconds counts from building the World on (docs/cli.md): the load and the
    # placement are not in it, the rest of the set-up is.
    stepping = s["wall_seconds"] - (setup["total"] - setup["load"] - setup["placement"])
    return {
        "robots": s["robots"], "regions": regions, "threads": s["threads"],
        "setup_s": s["setup_seconds"]["total"], "us_rs": 1e6 * stepping / (ticks * s["robots"]),
        "rtf": ticks / s["ticks_per_second"] / stepping, "tick_s": 1 / s["ticks_per_second"],
        "wall_ms": 1e3 * stepping / ticks,
        "phys_ms": 1e3 * stages["physics"] / ticks,
        "sense_cpu_ms": 1e3 * stages["sense"] / ticks,
        "ctrl_cpu_ms": 1e3 * stages["control"] / ticks,
    }


def regions_for(spec, threads):
    return threads if spec == "same" else int(spec)


def project(rows, cores):
    """Real-time factor at `cores` from the fitted per-tick costs (docs/scale.md).

    For each size: the single-thread run with one region gives the parallel work
    W = sense + control CPU; physics at K regions is fitted as M + P/K' from the runs
    at 1 thread (P + M) and K threads (P/K + M), M the serial part (ownership, ghosts,
    component updates) and P the regions' stepping; the rest of the tick (act, media, loop
    functions) is taken as serial: E = wall - physics - (sense + control)/threads.
    """
    out = []
    for n in sorted({r["robots"] for r in rows}):
        mine = [r for r in rows if r["robots"] == n]
        base = [r for r in mine if r["threads"] == 1 and r["regions"] == 1]
        split = [r for r in mine if r["regions"] > 1 and r["threads"] == r["regions"]]
        serial1 = [r for r in mine if r["threads"] == 1 and r["regions"] > 1]
        if not base or not split or not serial1:
            continue
        b, k = base[0], max(split, key=lambda r: r["regions"])
        k1 = [r for r in serial1 if r["regions"] == k["regions"]]
        if not k1:
            continue
        kk = k["regions"]
        # Clamped: on a busy machine the split run can come out slower than the serial one.
        p = min(k1[0]["phys_ms"], max(0.0, (k1[0]["phys_ms"] - k["phys_ms"]) * kk / (kk - 1)))
        m = k1[0]["phys_ms"] - p
        work = b["sense_cpu_ms"] + b["ctrl_cpu_ms"]
        extra = max(0.0, b["wall_ms"] - b["phys_ms"] - work)
        for c in cores:
            wall = extra + m + p / c + work / c
            out.append((n, c, c, 1e3 * b["tick_s"] / wall, m, p, work, extra))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--essaim", default=os.path.join(here, "..", "build", "essaim"))
    ap.add_argument("--dir", default=here, help="folder holding avoidance_1000.argos")
    ap.add_argument("--sizes", default="10000")
    ap.add_argument("--threads", default="1,2")
    ap.add_argument("--regions", default="1,same", help="region counts; 'same' = one per thread")
    ap.add_argument("--ticks", type=int, default=50)
    ap.add_argument("--json", help="also write every row to this JSON file")
    ap.add_argument("--project", default="", help="core counts to project to, e.g. 16,64")
    a = ap.parse_args()
    threads = [int(x) for x in a.threads.split(",")]
    pairs = [(t, k) for t in threads for k in sorted({regions_for(x, t) for x in a.regions.split(",")})]
    if a.project and (1, max(threads)) not in pairs:
        pairs.insert(1, (1, max(threads)))  # the fit needs the most regions on one thread
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for n in [int(x) for x in a.sizes.split(",")]:
            for t, k in pairs:
                rows.append(row(run_once(a, n, k, t, work), k))
                r = rows[-1]
                print(f"{r['robots']:>7} {k:>3} regions {t:>3} thr  set-up {r['setup_s']:6.2f} s"
                      f"  {r['us_rs']:7.2f} us/r-step  rtf {r['rtf']:6.2f}  tick {r['wall_ms']:8.1f} ms"
                      f"  (phys {r['phys_ms']:.1f}  sense {r['sense_cpu_ms']:.1f}  ctrl {r['ctrl_cpu_ms']:.1f} cpu-ms)",
                      flush=True)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)
    if a.project:
        print("projection: robots cores regions rtf  (serial-phys ms, region-phys ms, sense+ctrl cpu-ms, other ms)")
        for n, c, k, rtf, m, p, work, extra in project(rows, [int(x) for x in a.project.split(",")]):
            print(f"{n:>7} {c:>4} {k:>4} {rtf:6.2f}  ({m:.1f}, {p:.1f}, {work:.1f}, {extra:.1f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
