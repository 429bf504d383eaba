-- Loop functions for the sweep tests: a metrics.json shaped like the foraging one.
-- A "trip" here is a tick spent at x > 0 (source "A") or x <= 0 (source "B").
local per_robot = {}
local a, b = 0, 0

function init()
  for _, r in ipairs(experiment.robots) do
    per_robot[r.id] = 0
  end
end

function post_step()
  for _, r in ipairs(experiment.robots) do
    local x = r:position()
    if x > 0 then a = a + 1 else b = b + 1 end
    per_robot[r.id] = per_robot[r.id] + 1
  end
end

function post_experiment()
  local n = #experiment.robots
  return {
    ticks = experiment.tick,
    robots = n,
    trips_total = a + b,
    trips_per_source = {A = a, B = b},
    trips_per_robot = per_robot,
    trips_per_robot_mean = (a + b) / n,
    sources = {
      {name = "A", x = 1.0, y = 0.0, radius = 0.5, discovered_tick = 1, trips = a},
      {name = "B", x = -1.0, y = 0.0, radius = 0.5, discovered_tick = 2, trips = b},
    },
    discovered_count = 2,
    first_discovery_tick = 1,
    all_discovered_tick = 2,
    dead_robots = {{robot = experiment.robots[1].id, tick = experiment.tick}},
    dead_count = 1,
    dead_fraction = 1 / n,
  }
end
