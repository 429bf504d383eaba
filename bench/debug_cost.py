"""What `essaim debug` costs (docs/debugging.md), driven by the tests' DAP client
(tests/debug/dap_client.py):

1. a debug run without breakpoints against `essaim run`: the same experiment, seed and
   ticks, the process's CPU time (user + system) less that of a 1-tick run of the same kind
   (loading, init(), outputs), best of --repeat; and a debug run with one breakpoint in
   step() whose condition never holds (line hooks in every robot's state);
2. going back one tick in the middle of a long run: a session paused before tick --at of a
   --back-ticks run (runToTick), then stepBack on a robot's thread, timed from the request
   to its stopped event, --steps times in a row (each one tick further back): the wall time
   the client waits, and the CPU time of the session's processes (the front process that
   holds the connection, the simulation, its checkpoints: essaim forks one every 0.2 s of
   CPU time and a step back wakes the newest one before the target, which re-simulates);
   also the runToTick itself.

Figures go to stdout with the machine (lscpu's model) and the load average.

  .venv/bin/python bench/debug_cost.py --essaim build/essaim
  .venv/bin/python bench/debug_cost.py --essaim build/essaim --quick   # a few seconds
"""
import argparse
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "debug"))
from dap_client import DapClient  # noqa: E402  (the tests' client, not a package)

ARGOS = ROOT / "arenas" / "foraging.argos"


def children_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_cpu(essaim, ticks, seed, out) -> float:
    before = children_cpu()
    subprocess.run([essaim, "run", str(ARGOS), "--ticks", str(ticks), "--seed", str(seed), "--quiet",
                    "--out", str(out)], check=True, capture_output=True)
    return children_cpu() - before


def debug_cpu(essaim, ticks, seed, out, breakpoints=None) -> float:
    """A whole session: initialize, launch, the breakpoints, configurationDone, the end."""
    before = children_cpu()
    dap = DapClient.stdio(essaim, [ARGOS, "--ticks", ticks, "--seed", seed, "--out", out], cwd=out.parent,
                          timeout=3600)
    try:
        dap.start(breakpoints=breakpoints)
        if dap.finish(timeout=3600) != 0:
            raise SystemExit(f"essaim debug failed:\n{dap.stderr()[-2000:]}")
    finally:
        dap.kill()
    return children_cpu() - before


def debug_never_cpu(essaim, ticks, seed, out) -> float:
    """A session with one breakpoint in every robot's step() whose condition never holds:
    the line hooks in every state and the condition evaluated at each pass."""
    script = ROOT / "controllers" / "foraging.lua"
    line = next(n for n, text in enumerate(script.read_text().splitlines(), 1) if "set_velocity" in text)
    return debug_cpu(essaim, ticks, seed, out, {script: [{"line": line, "condition": 'robot.id == "none"'}]})


def best_net(measure, essaim, ticks, seed, folder, repeat) -> float:
    """min over `repeat` of measure(ticks) - measure(1): the CPU time of the ticks alone."""
    folder.mkdir(parents=True, exist_ok=True)
    net = []
    for k in range(repeat):
        full = measure(essaim, ticks, seed, folder / f"full-{k}")
        empty = measure(essaim, 1, seed, folder / f"one-{k}")
        net.append(full - empty)
    return min(net)


def session_cpus(marker: str) -> dict:
    """pid -> CPU seconds (utime, stime and what it reaped) of every process whose command
    line holds `marker` (the session's --out folder): the front process, the simulation and
    its checkpoints, which outlive the simulation they were forked from (reparented to init)."""
    found = {}
    for entry in Path("/proc").iterdir():
        try:
            if not entry.name.isdigit() or marker.encode() not in (entry / "cmdline").read_bytes():
                continue
            fields = (entry / "stat").read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        found[int(entry.name)] = sum(int(x) for x in fields[11:15]) / os.sysconf("SC_CLK_TCK")
    return found


def spent(before: dict, after: dict) -> float:
    """CPU seconds spent between two session_cpus(): by the processes alive at the end (a
    woken checkpoint's copy is new, its times start at 0; the process it replaced has exited)."""
    return sum(cpu - before.get(pid, 0.0) for pid, cpu in after.items())


def step_back_times(essaim, ticks, at, steps, seed, folder):
    """((wall, CPU) seconds of runToTick `at`, [(wall, CPU) seconds of each stepBack])."""
    out = folder / "back"
    dap = DapClient.stdio(essaim, [ARGOS, "--ticks", ticks, "--seed", seed, "--out", out], cwd=folder, timeout=3600)
    try:
        dap.start(stop_on_entry=True)
        thread = dap.stopped()["threadId"]
        robot = min(t for t in dap.threads().values() if t >= 2)  # the first robot's thread
        cpu0, t0 = session_cpus(str(out)), time.perf_counter()
        stop = dap.resume("runToTick", thread, tick=at)
        forward = (time.perf_counter() - t0, spent(cpu0, session_cpus(str(out))))
        assert stop["reason"] == "goto", stop
        back = []
        for _ in range(steps):
            cpu0, t0 = session_cpus(str(out)), time.perf_counter()
            stop = dap.resume("stepBack", robot)
            back.append((time.perf_counter() - t0, spent(cpu0, session_cpus(str(out)))))
            assert stop["reason"] == "step", stop
        dap.request("terminate")
        dap.finish(timeout=3600)
        return forward, back
    finally:
        dap.kill()


def machine() -> str:
    """lscpu's model name, CPU family and caches, and the CPU count."""
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True, timeout=10).stdout
    except (OSError, subprocess.SubprocessError):
        return f"{platform.processor() or 'unknown CPU'}, {os.cpu_count()} CPUs"
    info = {k.strip(): v.strip() for k, _, v in (line.partition(":") for line in out.splitlines())}
    caches = ", ".join(f"{c} {info[c + ' cache']}" for c in ("L2", "L3") if c + " cache" in info)
    return (f"{info.get('Model name', 'unknown CPU')} (family {info.get('CPU family', '?')}), "
            f"{os.cpu_count()} CPUs, {caches}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--essaim", default=str(ROOT / "build" / "essaim"))
    ap.add_argument("--ticks", type=int, default=2000, help="ticks of the run-cost comparison")
    ap.add_argument("--repeat", type=int, default=3, help="runs of each kind; the best is kept")
    ap.add_argument("--back-ticks", type=int, default=10000, help="length of the step-back run")
    ap.add_argument("--at", type=int, default=5000, help="the tick the step-back run pauses before")
    ap.add_argument("--steps", type=int, default=5, help="stepBack requests in a row")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--quick", action="store_true", help="200 ticks, 1 repeat, step back at 500 of 1000")
    a = ap.parse_args()
    if a.quick:
        a.ticks, a.repeat, a.back_ticks, a.at, a.steps = 200, 1, 1000, 500, 2
    essaim = str(Path(a.essaim).resolve())
    print(f"# bench/debug_cost.py, {time.strftime('%Y-%m-%d')}, {machine()}; "
          f"load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    print(f"# arenas/foraging.argos (30 robots), seed {a.seed}")
    with tempfile.TemporaryDirectory(prefix="debug-cost-") as tmp:
        folder = Path(tmp)
        run = best_net(run_cpu, essaim, a.ticks, a.seed, folder / "run", a.repeat)
        dbg = best_net(debug_cpu, essaim, a.ticks, a.seed, folder / "debug", a.repeat)
        print(f"run without breakpoints, {a.ticks} ticks, CPU s (best of {a.repeat}, less a 1-tick run):")
        print(f"  essaim run    {run:8.3f}")
        print(f"  essaim debug  {dbg:8.3f}   debug/run {dbg / run:5.2f}")
        hooked = best_net(debug_never_cpu, essaim, a.ticks, a.seed, folder / "hooked", a.repeat)
        print(f"  essaim debug, a breakpoint in step() whose condition never holds"
              f"  {hooked:8.3f}   /run {hooked / run:5.2f}")
        forward, back = step_back_times(essaim, a.back_ticks, a.at, a.steps, a.seed, folder)
        walls, cpus = [w for w, _ in back], [c for _, c in back]
        print(f"step back at tick {a.at} of a {a.back_ticks}-tick run (the first robot's thread):")
        print(f"  runToTick {a.at} from tick 0: wall s {forward[0]:.3f}, CPU s {forward[1]:.3f}")
        print(f"  stepBack, wall s (each)  {' '.join(f'{t:.3f}' for t in walls)}"
              f"   median {statistics.median(walls):.3f}  max {max(walls):.3f}")
        print(f"  stepBack, CPU s (each)   {' '.join(f'{t:.3f}' for t in cpus)}"
              f"   median {statistics.median(cpus):.3f}  (the session's processes, clock ticks of 10 ms)")
    print(f"# load average after {' '.join(f'{x:.2f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
