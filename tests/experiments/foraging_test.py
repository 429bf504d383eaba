"""The report's foraging experiment run by essaim (arenas/foraging*.argos).

The runs need the binary: set ESSAIM to its path (ctest does); without it those tests are skipped.
The arena checks run everywhere. Runs are small (few robots, a few thousand ticks) and use a
fixed seed; the assertions are about mechanisms, not performance:
  * a source is discovered, trips are made, and a robot mines a source it was told about over
    range-and-bearing before it ever touched one (metrics' informed_robots, from the LED colour
    the controller shows while heading to a source: arenas/foraging_loop.lua);
  * in omniscient mode (known_sources) robots mine from the first tick;
  * a controller that never goes home dies when its battery runs out: 100 units / 0.2 per tick
    = tick 500;
  * same file, same seed: the same metrics;
  * robots that know the sources spread their trips over them, more as the swarm grows, mine the
    far ones at the report's drain too, and jam at 60 (a cheap version of docs/foraging.md's
    targets).
"""

import csv
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
ARENAS = ROOT / "arenas"
VARIANTS = ["foraging.argos", "foraging_no_obstacles.argos", "foraging_5_sources.argos",
            "foraging_known.argos"]
NEVER_HOME = ROOT / "tests" / "experiments" / "never_home.lua"
MINING_LED = "255,255,0"


# Every device the foraging arenas declare (sensors and actuators).
DEVICES = {"differential_steering", "footbot_proximity", "footbot_distance_scanner",
           "footbot_base_ground", "range_and_bearing", "positioning", "battery", "leds"}


def unsupported_devices(essaim):
    """Devices of the arenas that `essaim devices` lists as not supported yet."""
    out = subprocess.run([essaim, "devices"], capture_output=True, text=True, timeout=60).stdout
    missing = set()
    for line in out.splitlines():
        line = line.strip()
        if line.startswith("<") and "not supported" in line:
            name = line[1:].split()[0].rstrip(">")
            if name in DEVICES:
                missing.add(name)
    return sorted(missing)


@pytest.fixture(scope="module")
def essaim():
    path = os.environ.get("ESSAIM")
    if not path:
        pytest.skip("ESSAIM is not set: point it at the essaim binary to run the foraging experiments")
    if not Path(path).exists():
        pytest.skip(f"ESSAIM={path} does not exist (build essaim first)")
    missing = unsupported_devices(path)
    if missing:
        pytest.skip("essaim does not support these foraging devices yet: " + ", ".join(missing))
    return path


def run(essaim, arena, out, ticks, sets=(), seed=1):
    cmd = [essaim, "run", str(ARENAS / arena), "--ticks", str(ticks), "--seed", str(seed),
           "--out", str(out), "--quiet"]
    for s in sets:
        cmd += ["--set", s]
    proc = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=540)
    assert proc.returncode == 0, f"{' '.join(cmd)}\nstdout:\n{proc.stdout}\nstderr:\n{proc.stderr}"
    summary = json.loads((out / "summary.json").read_text())
    assert summary["controller_errors"] == [], summary["controller_errors"]
    assert summary["ticks"] == ticks
    metrics = json.loads((out / "metrics.json").read_text())
    return summary, metrics


def as_dict(value):
    """An empty Lua table is written as []: read it as an empty object where one is meant."""
    return {} if value == [] else value


def check_schema(m, robots, ticks, source_names):
    assert m["ticks"] == ticks
    assert m["robots"] == robots
    per_source = as_dict(m["trips_per_source"])
    per_robot = as_dict(m["trips_per_robot"])
    assert sorted(per_source) == sorted(source_names)
    assert len(per_robot) == robots
    assert m["trips_total"] == sum(per_source.values()) == sum(per_robot.values())
    assert m["trips_per_robot_mean"] == pytest.approx(m["trips_total"] / robots, abs=1e-4)
    assert [s["name"] for s in m["sources"]] == source_names
    for s in m["sources"]:
        assert {"name", "x", "y", "radius", "trips"} <= set(s)
        assert s["trips"] == per_source[s["name"]]
        assert ("discovered_tick" in s) == ("discovered_by" in s)
    discovered = [s for s in m["sources"] if "discovered_tick" in s]
    assert m["discovered_count"] == len(discovered)
    if discovered:
        assert m["first_discovery_tick"] == min(s["discovered_tick"] for s in discovered)
    else:
        assert "first_discovery_tick" not in m
    if len(discovered) == len(source_names):
        assert m["all_discovered_tick"] == max(s["discovered_tick"] for s in discovered)
    else:
        assert "all_discovered_tick" not in m
    assert m["dead_count"] == len(m["dead_robots"])
    assert m["dead_fraction"] == pytest.approx(m["dead_count"] / robots, abs=1e-4)


# --- the arena files ------------------------------------------------------------------------------

def test_arenas_are_generated_and_up_to_date():
    proc = subprocess.run([sys.executable, str(ROOT / "tools" / "make_foraging_arena.py"), "--check"],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr


@pytest.mark.parametrize("name", VARIANTS)
def test_arena_contents(name):
    root = ET.parse(ARENAS / name).getroot()
    exp = root.find("framework/experiment")
    assert exp.get("ticks_per_second") == "10" and exp.get("length") == "1000"
    assert exp.get("random_seed") == "1"
    ctrl = root.find("controllers/lua_controller")
    assert ctrl.get("id") == "foraging"
    assert {e.tag for e in ctrl.find("sensors")} == {
        "differential_steering", "footbot_proximity", "footbot_distance_scanner",
        "footbot_base_ground", "range_and_bearing", "positioning", "battery"}
    assert {e.tag for e in ctrl.find("actuators")} == {
        "differential_steering", "footbot_distance_scanner", "range_and_bearing", "leds"}
    params = ctrl.find("params")
    assert params.get("script") == "../controllers/foraging.lua"
    assert (ARENAS / params.get("script")).resolve() == (ROOT / "controllers" / "foraging.lua")
    assert ("known_sources" in params.attrib) == (name == "foraging_known.argos")
    lf = root.find("loop_functions")
    assert lf.get("script") == "foraging_loop.lua" and lf.get("nest") == "0,0,0.5"
    names = [s.split(":")[0] for s in lf.get("sources").split(";")]
    assert names == (["A", "B", "C", "D", "E"] if "5_sources" in name else ["A", "B", "C"])
    arena = root.find("arena")
    assert arena.find("floor").get("source") == "loop_functions"
    assert len(arena.findall("box")) == 4
    cylinders = arena.findall("cylinder")
    assert len(cylinders) == (0 if "no_obstacles" in name else 75)
    entity = arena.find("distribute/entity")
    assert entity.get("quantity") == "30" and entity.get("max_trials") == "100"
    bot = entity.find("foot-bot")
    assert bot.get("rab_range") == "3" and bot.get("rab_data_size") == "10"
    assert bot.find("battery").get("delta") == "0.002"
    assert root.find("media/range_and_bearing").get("check_occlusions") == "true"
    assert root.find("media/led").get("id") == "leds"
    assert root.find("physics_engines/dynamics2d").get("iterations") == "10"


# --- runs -------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name", VARIANTS)
def test_essaim_check_accepts_the_arenas(essaim, name):
    proc = subprocess.run([essaim, "check", str(ARENAS / name)], cwd=ROOT, capture_output=True,
                          text=True, timeout=120)
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_sources_are_found_shared_and_mined(essaim, tmp_path):
    robots, ticks = 10, 3000
    _, m = run(essaim, "foraging.argos", tmp_path / "run", ticks, sets=[
        f"arena.distribute.entity.quantity={robots}",
        # every robot told about a source goes mining, so sharing shows in a short run
        "controllers.foraging.params.MINE_PROB_WHEN_SRC_RECVD=1",
    ])
    check_schema(m, robots, ticks, ["A", "B", "C"])
    assert m["discovered_count"] >= 1, m
    assert m["trips_total"] >= 1, m
    per_robot = as_dict(m["trips_per_robot"])
    informed = m["informed_robots"]
    assert informed, "no robot headed for a source before touching one: nothing was shared"
    assert any(per_robot[r] >= 1 for r in informed), \
        f"no robot told about a source made a trip: informed={informed} trips={per_robot}"
    # discoverers touched their source themselves
    touches = as_dict(m["first_touch_by_robot"])
    for s in m["sources"]:
        if "discovered_by" in s:
            assert touches[s["discovered_by"]]["tick"] <= s["discovered_tick"]
    rows = list(csv.DictReader((tmp_path / "run" / "timeseries.csv").open()))
    assert [int(r["tick"]) for r in rows] == list(range(100, ticks + 1, 100))
    assert list(rows[0]) == ["tick", "trips_A", "trips_B", "trips_C", "trips_total", "alive"]
    assert int(rows[-1]["trips_total"]) == m["trips_total"]


def test_omniscient_robots_mine_from_the_start(essaim, tmp_path):
    robots, ticks = 8, 1500
    _, m = run(essaim, "foraging_known.argos", tmp_path / "run", ticks,
               sets=[f"arena.distribute.entity.quantity={robots}"])
    check_schema(m, robots, ticks, ["A", "B", "C"])
    assert m["trips_total"] >= robots, m
    per_source = as_dict(m["trips_per_source"])
    assert per_source["A"] == max(per_source.values()), "the nearest source should be the busiest"
    assert len(m["informed_robots"]) == robots, "known sources: yellow before any touch"


def test_same_seed_same_metrics(essaim, tmp_path):
    sets = ["arena.distribute.entity.quantity=6"]
    _, a = run(essaim, "foraging_known.argos", tmp_path / "a", 800, sets=sets, seed=7)
    _, b = run(essaim, "foraging_known.argos", tmp_path / "b", 800, sets=sets, seed=7)
    assert a == b
    assert (tmp_path / "a" / "timeseries.csv").read_text() == (tmp_path / "b" / "timeseries.csv").read_text()


def test_a_robot_that_never_goes_home_dies_at_tick_500(essaim, tmp_path):
    robots, ticks = 8, 600
    _, m = run(essaim, "foraging.argos", tmp_path / "run", ticks, sets=[
        f"arena.distribute.entity.quantity={robots}",
        f"controllers.foraging.params.script={NEVER_HOME}",
        # start far from the nest, where nothing refills them (never_home.lua keeps away from it)
        "arena.distribute.position.min=-4.5,1.5,0",
        "arena.distribute.position.max=-1.5,4.5,0",
    ])
    check_schema(m, robots, ticks, ["A", "B", "C"])
    assert m["dead_count"] == robots, m["dead_robots"]
    assert m["dead_fraction"] == 1
    assert sorted(d["robot"] for d in m["dead_robots"]) == sorted(f"fb{i}" for i in range(robots))
    for d in m["dead_robots"]:
        assert abs(d["tick"] - 500) <= 2, d       # 100 units at 0.2 per tick
    assert m["trips_total"] == 0
    rows = {int(r["tick"]): r for r in csv.DictReader((tmp_path / "run" / "timeseries.csv").open())}
    assert int(rows[400]["alive"]) == robots
    assert int(rows[600]["alive"]) == 0


# --- how the swarm spreads over the sources (docs/foraging.md) ------------------------------------
# A cheap version of the targets measured there (10 000 ticks, seeds 1-5, median): fewer ticks and
# one seed, with margins the full runs keep. A drain is the controller's BATT_BY_STEP and the
# battery's own discharge together.

def drain_sets(robots, drain):
    return [f"arena.distribute.entity.quantity={robots}",
            f"controllers.foraging.params.BATT_BY_STEP={drain}",
            f"arena.distribute.entity.foot-bot.battery.delta={drain / 100}",
            "loop_functions.decisions=series"]


def spread_run(essaim, tmp_path, robots, drain, ticks=4000, seed=1):
    _, m = run(essaim, "foraging_known.argos", tmp_path / f"n{robots}_d{drain}_s{seed}", ticks,
               sets=drain_sets(robots, drain), seed=seed)
    check_schema(m, robots, ticks, ["A", "B", "C"])
    per_source = as_dict(m["trips_per_source"])
    assert m["trips_total"] > 0, m
    return m, {k: v / m["trips_total"] for k, v in per_source.items()}


def test_the_swarm_spreads_over_the_sources_more_as_it_grows(essaim, tmp_path):
    m10, share10 = spread_run(essaim, tmp_path, 10, 0.1)
    m30, share30 = spread_run(essaim, tmp_path, 30, 0.1)
    assert share10["A"] <= 0.85, share10
    assert share30["A"] < share10["A"], (share10, share30)
    # every source was picked by the epsilon-greedy draw, both ways
    for m in (m10, m30):
        assert sum(m["chose_greedy"].values()) > sum(m["chose_epsilon"].values()) > 0, m
        assert all(m["chose_epsilon"][s] > 0 for s in ("B", "C")), m["chose_epsilon"]


def test_far_sources_are_mined_at_the_reports_drain_and_the_jam_stays(essaim, tmp_path):
    # The far sources' share over seeds 1-3, median: one seed's can fall either side of the
    # target (seed 1 gave 0.074 before the motion matched ARGoS's, 0.048 since; seeds 1-5 had
    # medians 0.074 and 0.089).
    runs = [spread_run(essaim, tmp_path, 10, 0.2, seed=seed) for seed in (1, 2, 3)]
    far = sorted(share["B"] + share["C"] for _, share in runs)
    assert far[1] >= 0.05, far
    m10 = runs[0][0]
    m60, _ = spread_run(essaim, tmp_path, 60, 0.2)
    assert m60["trips_per_robot_mean"] < m10["trips_per_robot_mean"] / 3, \
        (m10["trips_per_robot_mean"], m60["trips_per_robot_mean"])
