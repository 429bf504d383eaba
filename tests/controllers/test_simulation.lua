-- End to end in plain Lua: the foraging controller and loop functions in mockworld.lua, a small
-- kinematic stand-in for the simulator (see its header). Checks the behaviour as a whole, not
-- its performance: the real numbers come from essaim (tests/experiments/foraging_test.py).
local dir = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
package.path = dir .. "/?.lua;" .. dir .. "/../../controllers/?.lua;" .. package.path
local t = require "testlib"
local mw = require "mockworld"

local ROOT = dir .. "/../../"
local SOURCES = "A:-2.5,0,0.5;B:4.0,3.5,0.5;C:4.2,-4.2,0.5"
local DISCS = { { 0, 0, 0.5 }, { -2.5, 0, 0.5 }, { 4.0, 3.5, 0.5 }, { 4.2, -4.2, 0.5 } }

local function place(n, seed, x0, x1, y0, y1)
  local rng = mw.make_rng(seed)
  local robots = {}
  while #robots < n do
    local x, y = rng.uniform(x0, x1), rng.uniform(y0, y1)
    local ok = true
    for _, r in ipairs(robots) do
      if (r.x - x) ^ 2 + (r.y - y) ^ 2 < 0.04 then ok = false end
    end
    if ok then robots[#robots + 1] = { x = x, y = y, yaw = rng.uniform(-math.pi, math.pi) } end
  end
  return robots
end

local function world(opts)
  return mw.new({
    robots = opts.robots, cylinders = mw.scatter(opts.cylinders or 20, 0.1, 5, DISCS, 0.4, opts.seed),
    controller = ROOT .. (opts.controller or "controllers/foraging.lua"), params = opts.params or {},
    loop = ROOT .. "arenas/foraging_loop.lua", seed = opts.seed,
    loop_params = { nest = "0,0,0.5", sources = SOURCES, timeseries_every = "100",
                    mining_led = "255,255,0" },
  })
end

local function no_errors(w)
  t.eq(#w.errors, 0, table.concat(w.errors, "\n"))
end

t.test("omniscient mode: robots mine the known sources from the start", function()
  local w = world({ robots = place(6, 5, -1.2, 1.2, -1.2, 1.2), seed = 2,
                    params = { known_sources = "-2.5,0;4.0,3.5;4.2,-4.2" } })
  local m = w:run(1500)
  no_errors(w)
  t.ok(m.trips_total >= 12, "trips: " .. m.trips_total)
  t.ok(m.trips_per_source.A > m.trips_per_source.B, "the near source is the best")
  t.eq(#m.informed_robots, 6, "all of them knew where to go before touching anything")
  local mining = 0
  for _, rb in ipairs(w.robots) do
    local r, g, b = w.experiment.robots[rb.index]:led(1)
    if (r == 255 and g == 255 and b == 0) or (r == 255 and g == 140 and b == 0) then
      mining = mining + 1
    end
  end
  t.ok(mining >= 4, "most robots show a mining colour at the end")
end)

t.test("exploration: a source is found, shared over RAB, and mined by robots told about it", function()
  local w = world({ robots = place(8, 9, -1.2, 1.2, -1.2, 1.2), seed = 3,
                    params = { MINE_PROB_WHEN_SRC_RECVD = "1" } })
  local m = w:run(2500)
  no_errors(w)
  t.ok(m.discovered_count >= 1, "a source was discovered")
  t.ok(m.trips_total >= 5, "trips: " .. m.trips_total)
  local informed_with_trips = 0
  for _, id in ipairs(m.informed_robots) do
    if m.trips_per_robot[id] >= 1 then informed_with_trips = informed_with_trips + 1 end
  end
  t.ok(informed_with_trips >= 1, "a robot mined a source it never touched before being told")
  t.eq(#w.rows, 25, "one timeseries row per 100 ticks")
end)

t.test("battery: a robot that never goes home dies at tick 500 (100 units / 0.2)", function()
  local robots = place(5, 4, -4.5, -1.5, 1.5, 4.5)
  local w = world({ robots = robots, seed = 1, cylinders = 10,
                    controller = "tests/experiments/never_home.lua" })
  local m = w:run(520)
  no_errors(w)
  t.eq(m.dead_count, 5)
  t.eq(m.dead_fraction, 1.0)
  for _, d in ipairs(m.dead_robots) do
    t.ok(math.abs(d.tick - 500) <= 1, d.robot .. " died at " .. d.tick)
  end
end)

t.test("foraging robots manage their battery: nobody dies in a short explore run", function()
  local w = world({ robots = place(4, 13, -1.2, 1.2, -1.2, 1.2), seed = 5 })
  local m = w:run(1500)
  no_errors(w)
  t.eq(m.dead_count, 0)
end)

t.done()
