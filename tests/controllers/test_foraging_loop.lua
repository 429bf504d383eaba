-- The foraging loop functions (arenas/foraging_loop.lua) against a hand-driven fake experiment.
local dir = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
package.path = dir .. "/?.lua;" .. dir .. "/../../controllers/?.lua;" .. package.path
local t = require "testlib"

local LOOP = dir .. "/../../arenas/foraging_loop.lua"
local R = 0.085036758

local PARAMS = { nest = "0,0,0.5", sources = "A:-2.5,0,0.5;B:4.0,3.5,0.5;C:4.2,-4.2,0.5",
                 timeseries_every = "10" }

-- A fake experiment; returns the loop functions' environment and the robots' states.
local function setup(n, params)
  local exp = { tick = 0, ticks_per_second = 10, length_ticks = 0, seed = 1, params = params or PARAMS,
                robots = {}, output_dir = "." }
  local rows, logs = {}, {}
  exp.timeseries = function(row) rows[#rows + 1] = row end
  local states = {}
  for i = 1, n do
    local s = { x = 1, y = 1, charge = 1, alive = true, led = { 0, 0, 0 }, refills = 0,
                globals = {}, reads = 0 }
    states[i] = s
    local h = { id = "fb" .. (i - 1), index = i }
    function h.position() return s.x, s.y end
    function h.battery() return s.charge end
    function h.set_battery(_, c) s.charge = c; s.refills = s.refills + 1 end
    function h.alive() return s.alive end
    function h.kill() s.alive = false end
    function h.led() return s.led[1], s.led[2], s.led[3] end
    function h.lua_global(_, name) s.reads = s.reads + 1; return s.globals[name] end
    exp.robots[i] = h
  end
  local env = setmetatable({ experiment = exp, log = function(m) logs[#logs + 1] = m end },
                           { __index = _G })
  assert(loadfile(LOOP, "t", env))()
  env.init()
  local w = { env = env, exp = exp, s = states, rows = rows, logs = logs }
  function w.tick(k)
    for _ = 1, k or 1 do
      exp.tick = exp.tick + 1
      for _, st in ipairs(states) do
        if st.alive and st.drain then st.charge = math.max(0, st.charge - st.drain) end
      end
      env.pre_step()
      if env.post_step then env.post_step() end
    end
  end
  return w
end

-- Minimal JSON writer following the __jsontype convention, to check the table is writable.
local function json(v)
  local tv = type(v)
  if tv == "nil" then return "null" end
  if tv == "boolean" then return tostring(v) end
  if tv == "number" then
    if math.type(v) == "integer" then return tostring(v) end
    return string.format("%.17g", v)
  end
  if tv == "string" then return string.format("%q", v) end
  assert(tv == "table", "unexpected " .. tv)
  local mt = getmetatable(v)
  local kind = mt and mt.__jsontype or ((#v > 0 or next(v) == nil) and "array" or "object")
  local parts = {}
  if kind == "array" then
    for i = 1, #v do parts[i] = json(v[i]) end
    return "[" .. table.concat(parts, ",") .. "]"
  end
  local keys = {}
  for k in pairs(v) do assert(type(k) == "string", "object key " .. tostring(k)); keys[#keys + 1] = k end
  table.sort(keys)
  for _, k in ipairs(keys) do parts[#parts + 1] = string.format("%q", k) .. ":" .. json(v[k]) end
  return "{" .. table.concat(parts, ",") .. "}"
end

t.test("floor: black nest and sources, white elsewhere", function()
  local w = setup(1)
  local fc = w.env.floor_color
  local function grey(x, y) local r, g, b = fc(x, y); return r + g + b end
  t.eq(grey(0, 0), 0); t.eq(grey(0.49, 0), 0); t.eq(grey(0.51, 0), 765)
  t.eq(grey(-2.5, 0), 0); t.eq(grey(-2.5, 0.45), 0); t.eq(grey(-2.5, 0.55), 765)
  t.eq(grey(4.0, 3.5), 0); t.eq(grey(4.2, -4.2), 0)
  t.eq(grey(1, 1), 765); t.eq(grey(-4.9, 4.9), 765)
end)

t.test("floor_color works before init (the raster may be sampled first)", function()
  local exp = { params = PARAMS, robots = {} }
  local env = setmetatable({ experiment = exp }, { __index = _G })
  assert(loadfile(LOOP, "t", env))()
  local r = env.floor_color(0, 0)
  t.eq(r, 0)
end)

t.test("touch, discovery, trip, refill", function()
  local w = setup(2)
  local a = w.s[1]
  a.x, a.y = -2.5 + 0.5 + R + 0.001, 0          -- just not touching
  w.tick()
  t.eq(w.env.post_experiment().discovered_count, 0)
  a.x = -2.5 + 0.5 + R - 0.001                   -- touching
  w.tick(4)                                      -- tick 5
  a.charge = 0.3
  a.x, a.y = 1.5, 0
  w.tick()
  t.eq(a.charge, 0.3, "not refilled outside the nest")
  a.x = 0.5 + R - 0.001                          -- in the nest
  w.tick()
  t.eq(a.charge, 1)
  local m = w.env.post_experiment()
  t.eq(m.trips_total, 1)
  t.eq(m.trips_per_source.A, 1); t.eq(m.trips_per_source.B, 0)
  t.eq(m.trips_per_robot.fb0, 1); t.eq(m.trips_per_robot.fb1, 0)
  t.eq(m.sources[1].name, "A"); t.eq(m.sources[1].discovered_tick, 2)
  t.eq(m.sources[1].discovered_by, "fb0"); t.eq(m.sources[1].trips, 1)
  t.eq(m.discovered_count, 1); t.eq(m.first_discovery_tick, 2)
  t.eq(m.all_discovered_tick, nil, "not all discovered: absent")
  t.eq(m.sources[2].discovered_tick, nil, "undiscovered: absent")
  t.eq(m.first_touch_by_robot.fb0.source, "A"); t.eq(m.first_touch_by_robot.fb0.tick, 2)
  t.eq(m.first_touch_by_robot.fb1, nil)
  -- staying in the nest makes no second trip
  w.tick(3)
  t.eq(w.env.post_experiment().trips_total, 1)
end)

t.test("the last source touched gets the trip", function()
  local w = setup(1)
  local a = w.s[1]
  a.x, a.y = -2.5, 0; w.tick()
  a.x, a.y = 4.0, 3.5; w.tick()
  a.x, a.y = 0, 0; w.tick()
  local m = w.env.post_experiment()
  t.eq(m.trips_per_source.A, 0); t.eq(m.trips_per_source.B, 1)
  t.eq(m.sources[1].discovered_tick, 1); t.eq(m.sources[2].discovered_tick, 2)
end)

t.test("all discovered: first and last discovery ticks", function()
  local w = setup(3)
  w.s[1].x, w.s[1].y = 4.2, -4.2; w.tick(7)
  w.s[2].x, w.s[2].y = -2.5, 0.2; w.tick(5)
  w.s[3].x, w.s[3].y = 4.0, 3.5; w.tick()
  local m = w.env.post_experiment()
  t.eq(m.discovered_count, 3)
  t.eq(m.first_discovery_tick, 1); t.eq(m.all_discovered_tick, 13)
  t.eq(m.sources[3].discovered_by, "fb0")
end)

t.test("a robot whose battery reaches 0 dies, once", function()
  local w = setup(3)
  w.s[1].drain = 0.002          -- 100 units, 0.2 per tick: 500 ticks
  w.s[2].drain = 0.002
  w.s[2].x, w.s[2].y = 0, 0     -- in the nest: refilled every tick
  w.tick(600)
  t.ok(not w.s[1].alive); t.ok(w.s[2].alive); t.ok(w.s[3].alive)
  local m = w.env.post_experiment()
  t.eq(m.dead_count, 1)
  t.eq(#m.dead_robots, 1)
  t.eq(m.dead_robots[1].robot, "fb0")
  t.ok(m.dead_robots[1].tick >= 499 and m.dead_robots[1].tick <= 501, "dies at ~500")
  t.near(m.dead_fraction, 0.3333, 1e-9)
  t.eq(m.ticks, 600); t.eq(m.robots, 3)
end)

t.test("a dead robot is not refilled and makes no trip", function()
  local w = setup(1)
  local a = w.s[1]
  a.x, a.y = -2.5, 0
  w.tick()
  a.charge = 0
  w.tick()
  t.ok(not a.alive)
  a.x, a.y = 0, 0
  w.tick()
  local m = w.env.post_experiment()
  t.eq(a.charge, 0); t.eq(m.trips_total, 0); t.eq(m.dead_count, 1)
end)

t.test("timeseries every N ticks with cumulative trips and alive robots", function()
  local w = setup(2)
  w.s[1].x, w.s[1].y = -2.5, 0
  w.tick(3)
  w.s[1].x, w.s[1].y = 0, 0
  w.s[2].charge = 0
  w.tick(17)
  t.eq(#w.rows, 2)
  local names, values = {}, {}
  for i, kv in ipairs(w.rows[2]) do names[i] = kv[1]; values[i] = kv[2] end
  t.eq(table.concat(names, ","), "tick,trips_A,trips_B,trips_C,trips_total,alive")
  t.eq(table.concat(values, ","), "20,1,0,0,1,1")
  t.eq(w.rows[1][1][2], 10)
end)

t.test("metrics: exact schema, JSON-writable, empty arrays stay arrays", function()
  local w = setup(2)
  w.tick(5)
  local m = w.env.post_experiment()
  local keys = {}
  for k in pairs(m) do keys[#keys + 1] = k end
  table.sort(keys)
  t.eq(table.concat(keys, ","), "dead_count,dead_fraction,dead_robots,discovered_count," ..
       "first_touch_by_robot,robots,sources,ticks,trips_per_robot,trips_per_robot_mean," ..
       "trips_per_source,trips_total")
  local text = json(m)
  t.ok(text:find('"dead_robots":%[%]'), "empty dead_robots is []")
  t.ok(text:find('"first_touch_by_robot":{}'), "empty map is {}")
  t.ok(text:find('"sources":%[{'), "sources is an array of objects")
  t.eq(math.type(m.ticks), "integer"); t.eq(math.type(m.trips_total), "integer")
  t.eq(m.sources[1].x, -2.5); t.eq(m.sources[1].radius, 0.5)
  t.ok(#w.logs >= 3, "a summary is logged")
  t.ok(w.logs[1]:find("0/3 sources"), w.logs[1])
end)

t.test("informed robots: mining LED shown before touching any source", function()
  local params = {}
  for k, v in pairs(PARAMS) do params[k] = v end
  params.mining_led = "255,255,0"
  local w = setup(3, params)
  -- fb0 finds A itself, then shows yellow
  w.s[1].x, w.s[1].y = -2.5, 0; w.tick()
  w.s[1].led = { 255, 255, 0 }; w.tick()
  -- fb1 shows yellow first (told over RAB), then reaches A and makes a trip
  w.s[2].led = { 255, 255, 0 }; w.tick()
  w.s[2].x, w.s[2].y = -2.5, 0.3; w.tick()
  w.s[2].x, w.s[2].y = 0, 0; w.tick()
  -- fb2 shows orange only
  w.s[3].led = { 255, 140, 0 }; w.tick()
  local m = w.env.post_experiment()
  t.eq(#m.informed_robots, 1); t.eq(m.informed_robots[1], "fb1")
  t.eq(m.trips_per_robot.fb1, 1)
  t.ok(json(m):find('"informed_robots":%["fb1"%]'))
end)

local function with(over)
  local params = {}
  for k, v in pairs(PARAMS) do params[k] = v end
  for k, v in pairs(over) do params[k] = v end
  return params
end

-- What controllers/foraging.lua publishes when it takes a decision.
local function decide(s, tick, why, x, y)
  s.globals.decision_count = (s.globals.decision_count or 0) + 1
  s.globals.decision = { tick = tick, why = why, x = x, y = y, battery = 50, mu = 12.5 }
end

t.test("decisions off: nothing is read from the controllers", function()
  local w = setup(2)
  decide(w.s[1], 1, "greedy", -2.5, 0)
  w.tick(20)
  t.eq(w.s[1].reads + w.s[2].reads, 0)
  local m = w.env.post_experiment()
  t.eq(m.chose_greedy, nil); t.eq(#w.rows[1], 6)
end)

t.test("decisions: counted per source and reason, heading robots in the timeseries", function()
  local w = setup(3, with({ decisions = "series" }))
  decide(w.s[1], 1, "greedy", -2.5, 0)         -- A
  decide(w.s[2], 1, "epsilon", 4.0, 3.5)       -- B
  decide(w.s[3], 1, "greedy", -2.4, 0.2)       -- A (a robot's own estimate of it)
  w.tick(5)
  decide(w.s[2], 6, "battery")                 -- B given up: home
  w.tick(1)
  decide(w.s[2], 7, "epsilon", 4.2, -4.2)      -- C
  w.tick(4)
  local row = {}
  for _, kv in ipairs(w.rows[1]) do row[kv[1]] = kv[2] end
  t.eq(row.heading_A, 2); t.eq(row.heading_B, 0); t.eq(row.heading_C, 1)
  t.eq(row.chose_greedy_A, 2); t.eq(row.chose_epsilon_B, 1); t.eq(row.chose_epsilon_C, 1)
  t.eq(row.battery_returns, 1)
  local m = w.env.post_experiment()
  t.eq(m.chose_greedy.A, 2); t.eq(m.chose_greedy.B, 0); t.eq(m.chose_epsilon.C, 1)
  t.eq(m.battery_returns, 1); t.eq(m.started_message, 0)
  t.ok(json(m):find('"chose_epsilon":{'), "an object")
  t.eq(#w.logs, 3, "series only: the summary alone is logged")
end)

t.test("decisions log: one line per decision, read once", function()
  local w = setup(1, with({ decisions = "log" }))
  decide(w.s[1], 3, "message")
  w.tick(3)
  decide(w.s[1], 9, "greedy", 4.2, -4.2)
  w.tick(3)
  t.eq(w.logs[1], "decision 3 fb0 nest message battery=50.0 mu=12.50")
  t.eq(w.logs[2], "decision 9 fb0 C greedy battery=50.0 mu=12.50")
  t.eq(#w.logs, 2)
  t.eq(w.env.post_experiment().started_message, 1)
end)

t.test("bad parameters raise clear errors", function()
  t.raises(function() setup(1, with({ decisions = "yes" })) end, "decisions")
  t.raises(function() setup(1, { nest = "0,0", sources = "" }) end, "nest")
  t.raises(function() setup(1, { nest = "0,0,0.5", sources = "A:1,2" }) end, "sources")
  t.raises(function() setup(1, { nest = "0,0,0.5", sources = "A:1,2,x" }) end, "sources")
  t.raises(function() setup(1, { nest = "0,0,0.5", sources = "A:1,2,3;A:4,5,6" }) end, "twice")
  t.raises(function() setup(1, { nest = "0,0,0.5", sources = "", mining_led = "1,2" }) end, "mining_led")
end)

t.done()
