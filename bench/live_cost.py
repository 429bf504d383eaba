"""What `essaim serve` costs over `essaim run` (docs/live.md): the same experiment stepped
N ticks at full speed by `run`, by `serve` with no page open, and by `serve` with one live
page open in headless Chromium (Playwright; Debian's chromium).

The measure is the essaim process's CPU time for those N ticks (user + system, from
/proc): on a shared machine wall time mostly measures the other processes. For `run`, the
CPU time of a 1-tick run (loading, writing outputs) is subtracted; for `serve`, the CPU time
from the "run N ticks" command to the state saying it is done. Chromium's own CPU time is
not counted (it is the page's, not the simulator's) but printed.

  .venv/bin/python bench/live_cost.py --essaim build/essaim --ticks 200 --repeat 3
"""
import argparse
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCENARIOS = {
    "foraging-30": [],
    "foraging-300": ["arena.distribute.entity.quantity=300", "arena.distribute.position.min=-2.2,-2.2,0",
                     "arena.distribute.position.max=2.2,2.2,0"],
}
HZ = os.sysconf("SC_CLK_TCK")


def sets(overrides):
    return [a for o in overrides for a in ("--set", o)]


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_cpu(essaim, argos, overrides, ticks, out):
    """CPU seconds of `essaim run` for `ticks` ticks, less those of a 1-tick run."""
    def once(n):
        before = children_cpu()
        subprocess.run([essaim, "run", str(argos), "--ticks", str(n), "--quiet", "--out", str(out / f"r{n}"),
                        *sets(overrides)], check=True, capture_output=True)
        return children_cpu() - before
    return once(ticks) - once(1)


def proc_cpu(pid):
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / HZ  # utime, stime


def call(base, token, path, body=None):
    req = urllib.request.Request(base + path, data=body.encode() if body else None,
                                 headers={"Authorization": "Bearer " + token})
    with urllib.request.urlopen(req, timeout=30) as r:
        return json.loads(r.read())


def serve_cpu(essaim, argos, overrides, ticks, browser=None):
    """CPU seconds of `essaim serve` stepping `ticks` ticks at full speed, and the wall time."""
    proc = subprocess.Popen([essaim, "serve", str(argos), "--port", "0", *sets(overrides)],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    try:
        url = proc.stdout.readline().strip()
        base, token = url.split("/?token=")
        page = None
        if browser:
            page = browser.new_page(viewport={"width": 1200, "height": 760})
            page.goto(url)
            page.wait_for_function("window.essaimLive && essaimLive.frame()", timeout=60000)
        call(base, token, "/api/control", '{"cmd": "speed", "value": 0}')
        time.sleep(0.3)
        cpu0, t0 = proc_cpu(proc.pid), time.monotonic()
        call(base, token, "/api/control", json.dumps({"cmd": "run", "ticks": ticks}))
        while True:
            time.sleep(0.1)
            s = call(base, token, "/api/state")
            if s["tick"] >= ticks and s["paused"]:
                break
        cpu, wall = proc_cpu(proc.pid) - cpu0, time.monotonic() - t0
        frames = page.evaluate("essaimLive.frames") if page else 0
        if page:
            page.close()
        return cpu, wall, frames
    finally:
        proc.terminate()
        proc.wait(timeout=30)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--essaim", default=str(ROOT / "build" / "essaim"))
    ap.add_argument("--ticks", type=int, default=200)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--only", nargs="*", default=list(SCENARIOS))
    ap.add_argument("--no-page", action="store_true", help="skip the runs with a page open")
    a = ap.parse_args()
    argos = ROOT / "arenas" / "foraging.argos"
    chromium = shutil.which("chromium") or "/usr/bin/chromium"
    pw = browser = None
    if not a.no_page:
        from playwright.sync_api import sync_playwright
        pw = sync_playwright().start()
        browser = pw.chromium.launch(executable_path=chromium, args=["--headless", "--no-sandbox", "--disable-gpu"])
    out = Path(tempfile.mkdtemp(prefix="essaim-live-cost-"))
    print(f"{a.ticks} ticks, median of {a.repeat}; CPU seconds of the essaim process")
    print(f"{'scenario':<14} {'run':>7} {'serve':>7} {'+page':>7} {'serve/run':>9} {'+page/run':>9} {'frames':>6}")
    try:
        for name in a.only:
            ov = SCENARIOS[name]
            runs, serves, pages, frames = [], [], [], []
            for _ in range(a.repeat):  # interleaved, so a busy spell hits all three alike
                runs.append(run_cpu(a.essaim, argos, ov, a.ticks, out))
                serves.append(serve_cpu(a.essaim, argos, ov, a.ticks)[0])
                if browser:
                    cpu, _, n = serve_cpu(a.essaim, argos, ov, a.ticks, browser)
                    pages.append(cpu)
                    frames.append(n)
            r, s = statistics.median(runs), statistics.median(serves)
            p = statistics.median(pages) if pages else float("nan")
            print(f"{name:<14} {r:7.2f} {s:7.2f} {p:7.2f} {s / r:9.3f} {p / r:9.3f} "
                  f"{int(statistics.median(frames)) if frames else 0:6d}", flush=True)
    finally:
        shutil.rmtree(out, ignore_errors=True)
        if browser:
            browser.close()
            pw.stop()


if __name__ == "__main__":
    sys.exit(main())
