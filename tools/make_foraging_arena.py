#!/usr/bin/env python3
"""Generate the foraging experiment's .argos files (report "Robots en Essaim: Explorez", ch. 7).

A 10 m x 10 m walled arena, the nest (radius 0.5 m) at the origin, black source discs
(radius 0.5 m), 75 static cylinders placed at random, 30 foot-bots around the nest running
controllers/foraging.lua, and the rules in arenas/foraging_loop.lua.

Variants:
  foraging.argos               the report's configuration (fig. 7.1: sources A, B, C)
  foraging_no_obstacles.argos  same without the cylinders
  foraging_5_sources.argos     two more sources (D, E), obstacles placed around all five
  foraging_known.argos         foraging.argos with the robots told where the sources are
                               (report 7.1.1, omniscient mode: known_sources)
  foraging_30m.argos           a 30 m arena, 27 sources, 675 obstacles, 1000 robots (benchmark)

Deterministic: the obstacles come from this script's own seed, never from the clock, so running
it again rewrites identical files. Standard library only.

    python3 tools/make_foraging_arena.py            # write arenas/*.argos
    python3 tools/make_foraging_arena.py --check    # exit 1 if the files are not up to date
"""

import argparse
import math
import random
import sys
from pathlib import Path

SEED = 20140507          # obstacle layout seed (fixed: the layout is part of the experiment)
HALF = 5.0               # inner half-size of the arena (m): 10 m x 10 m inside the walls
WALL_THICKNESS = 0.1
WALL_HEIGHT = 0.5
NEST = (0.0, 0.0, 0.5)
SOURCES_3 = [("A", -2.5, 0.0, 0.5), ("B", 4.0, 3.5, 0.5), ("C", 4.2, -4.2, 0.5)]
SOURCES_5 = SOURCES_3 + [("D", -3.8, 3.8, 0.5), ("E", 0.5, -3.8, 0.5)]
OBSTACLES = 75
OBSTACLE_RADIUS = 0.1
OBSTACLE_HEIGHT = 0.2
CLEARANCE = 0.4          # free gap around obstacles: to discs, walls and each other (m)
ROBOTS = 30
START_BOX = 1.2          # robots start uniformly in [-START_BOX, START_BOX]^2
TICKS_PER_SECOND = 10
LENGTH_S = 1000
RANDOM_SEED = 1
BATTERY_DELTA = 0.002    # 100 units, 0.2 per tick

# Listing 7.1, written out so that sweeps can --set them (the controller has the same defaults).
CONTROLLER_PARAMS = [
    ("BASE_SPEED", "30"), ("BATT_BY_STEP", "0.2"),
    ("SCANNER_RPM", "75"), ("DIR_NUMBER", "15"), ("EXPL_DIR_NUMBER", "20"), ("EXPL_CONV", "3"),
    ("CONVERGENCE", "1"), ("OBSTACLE_PROXIMITY_DEPENDANCE", "0.25"),
    ("OBSTACLE_DIRECTION_DEPENDANCE", "0.25"), ("EMER_DIR_DEP", "1"), ("EMER_PROX_DEP", "1"),
    ("MIN_SPEED_COEFF", "0.6"), ("RANDOM_SPEED_TIME", "30"),
    ("ORGN_SRC_DST", "80"), ("MINE_PROB_WHEN_SRC_RECVD", "0.2"), ("INIT_BATT_SEC", "25"),
    ("IDEAL_NEST_BATT", "20"), ("EPSILONGREED", "0.1"),
]


def num(v):
    """Short, stable decimal text for a coordinate."""
    text = f"{v:.3f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def place_obstacles(rng, discs, count, half=HALF):
    """`count` cylinder centres, uniform over the arena, rejecting any closer than CLEARANCE
    (surface to surface) to a disc, a wall or another cylinder."""
    r = OBSTACLE_RADIUS
    lim = half - r - CLEARANCE
    placed = []
    tries = 0
    while len(placed) < count:
        tries += 1
        if tries > 200000:
            raise RuntimeError(f"could only place {len(placed)} of {count} obstacles")
        x, y = rng.uniform(-lim, lim), rng.uniform(-lim, lim)
        if any(math.hypot(x - dx, y - dy) < dr + r + CLEARANCE for dx, dy, dr in discs):
            continue
        if any(abs(x - ox) < 2 * r + CLEARANCE and math.hypot(x - ox, y - oy) < 2 * r + CLEARANCE
               for ox, oy in placed):
            continue
        placed.append((round(x, 3), round(y, 3)))
    return placed


def walls(half=HALF):
    out = []
    c = half + WALL_THICKNESS / 2
    long_side = 2 * half + 2 * WALL_THICKNESS
    for wid, x, y, sx, sy in (("wall_north", 0, c, long_side, WALL_THICKNESS),
                              ("wall_south", 0, -c, long_side, WALL_THICKNESS),
                              ("wall_east", c, 0, WALL_THICKNESS, long_side),
                              ("wall_west", -c, 0, WALL_THICKNESS, long_side)):
        out.append(f'    <box id="{wid}" size="{num(sx)},{num(sy)},{num(WALL_HEIGHT)}" movable="false">\n'
                   f'      <body position="{num(x)},{num(y)},0" orientation="0,0,0"/>\n'
                   f'    </box>')
    return "\n".join(out)


def arena_xml(name, description, sources, obstacles, known, half=HALF, robots=ROBOTS, start_box=START_BOX):
    src_attr = ";".join(f"{n}:{num(x)},{num(y)},{num(r)}" for n, x, y, r in sources)
    params = [("script", "../controllers/foraging.lua")] + CONTROLLER_PARAMS + [
        ("NEST_X", num(NEST[0])), ("NEST_Y", num(NEST[1])), ("NEST_RADIUS", num(NEST[2]))]
    if known:
        params.append(("known_sources", ";".join(f"{num(x)},{num(y)}" for _, x, y, _ in sources)))
    params_xml = "\n".join(f"              {k}=\"{v}\"" for k, v in params)
    cylinders = "\n".join(
        f'    <cylinder id="obstacle{i}" radius="{num(OBSTACLE_RADIUS)}" '
        f'height="{num(OBSTACLE_HEIGHT)}" movable="false">\n'
        f'      <body position="{num(x)},{num(y)},0" orientation="0,0,0"/>\n'
        f'    </cylinder>'
        for i, (x, y) in enumerate(obstacles))
    size = 2 * (half + 2 * WALL_THICKNESS)
    return f'''<?xml version="1.0" ?>
<!-- {name}: {description}
     Generated by tools/make_foraging_arena.py (seed {SEED}); edit the script, not this file. -->
<argos-configuration>

  <framework>
    <system threads="0"/>
    <experiment length="{LENGTH_S}" ticks_per_second="{TICKS_PER_SECOND}" random_seed="{RANDOM_SEED}"/>
  </framework>

  <controllers>
    <lua_controller id="foraging">
      <actuators>
        <differential_steering implementation="default"/>
        <footbot_distance_scanner implementation="default"/>
        <range_and_bearing implementation="default"/>
        <leds implementation="default" medium="leds"/>
      </actuators>
      <sensors>
        <differential_steering implementation="default"/>
        <footbot_proximity implementation="default" show_rays="false"/>
        <footbot_distance_scanner implementation="rot_z_only" show_rays="false"/>
        <footbot_base_ground implementation="rot_z_only"/>
        <range_and_bearing implementation="medium" medium="rab" show_rays="false"/>
        <positioning implementation="default"/>
        <battery implementation="default"/>
      </sensors>
      <params {params_xml.lstrip()}/>
    </lua_controller>
  </controllers>

  <loop_functions script="foraging_loop.lua"
                  nest="{num(NEST[0])},{num(NEST[1])},{num(NEST[2])}"
                  sources="{src_attr}"
                  timeseries_every="100"
                  mining_led="255,255,0"/>

  <arena size="{num(size)},{num(size)},1" center="0,0,0.5">
    <floor id="floor" source="loop_functions" pixels_per_meter="50"/>

{walls(half)}
{cylinders + chr(10) if cylinders else ""}
    <distribute>
      <position method="uniform" min="{num(-start_box)},{num(-start_box)},0" max="{num(start_box)},{num(start_box)},0"/>
      <orientation method="uniform" min="0,0,0" max="360,0,0"/>
      <entity quantity="{robots}" max_trials="100">
        <foot-bot id="fb" rab_range="3" rab_data_size="10">
          <controller config="foraging"/>
          <battery discharge_model="time" delta="{BATTERY_DELTA}"/>
        </foot-bot>
      </entity>
    </distribute>
  </arena>

  <physics_engines>
    <dynamics2d id="dyn2d" iterations="10"/>
  </physics_engines>

  <media>
    <range_and_bearing id="rab" check_occlusions="true"/>
    <led id="leds"/>
  </media>

</argos-configuration>
'''


def discs_of(sources):
    return [NEST] + [(x, y, r) for _, x, y, r in sources]


def scaled_sources(tiles):
    """The report's three sources repeated in each 10 m tile of a (tiles x tiles) arena, named
    A1, B1, C1, A2, ...: the same source density as the 10 m arena."""
    out = []
    k = 0
    for ty in range(tiles):
        for tx in range(tiles):
            k += 1
            ox, oy = (tx - (tiles - 1) / 2) * 2 * HALF, (ty - (tiles - 1) / 2) * 2 * HALF
            out += [(f"{n}{k}", x + ox, y + oy, r) for n, x, y, r in SOURCES_3]
    return out


def variants():
    """{file name: xml text} for every variant."""
    sources_30m = scaled_sources(3)
    obstacles_30m = place_obstacles(random.Random(SEED + 30), discs_of(sources_30m), 9 * OBSTACLES, half=3 * HALF)
    obstacles_3 = place_obstacles(random.Random(SEED), discs_of(SOURCES_3), OBSTACLES)
    obstacles_5 = place_obstacles(random.Random(SEED + 5), discs_of(SOURCES_5), OBSTACLES)
    return {
        "foraging.argos": arena_xml(
            "foraging", "the report's foraging experiment (fig. 7.1), 30 robots, 3 sources",
            SOURCES_3, obstacles_3, known=False),
        "foraging_no_obstacles.argos": arena_xml(
            "foraging_no_obstacles", "foraging.argos without the obstacles",
            SOURCES_3, [], known=False),
        "foraging_5_sources.argos": arena_xml(
            "foraging_5_sources", "foraging with five sources (A, B, C plus D, E)",
            SOURCES_5, obstacles_5, known=False),
        "foraging_known.argos": arena_xml(
            "foraging_known", "foraging.argos in omniscient mode (report 7.1.1): the robots "
            "know the sources from the start", SOURCES_3, obstacles_3, known=True),
        "foraging_30m.argos": arena_xml(
            "foraging_30m", "foraging scaled up: a 30 m arena with 9x the sources and obstacles, "
            "1000 robots (the speed benchmark's large case)", sources_30m, obstacles_30m, known=False,
            half=3 * HALF, robots=1000, start_box=6.0),
    }


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out-dir", default=str(Path(__file__).resolve().parent.parent / "arenas"),
                    help="folder to write into (default: the repository's arenas/)")
    ap.add_argument("--check", action="store_true",
                    help="write nothing; exit 1 if a file is missing or differs")
    args = ap.parse_args(argv)
    out = Path(args.out_dir)
    stale = []
    for name, text in variants().items():
        path = out / name
        if args.check:
            if not path.exists() or path.read_text() != text:
                stale.append(name)
        else:
            out.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
            print(f"wrote {path}")
    if stale:
        print("out of date: " + ", ".join(stale) + " (run tools/make_foraging_arena.py)",
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
