-- Loop functions of the foraging experiment (report "Robots en Essaim: Explorez", chapter 7).
--
-- The rules hold for any controller, whatever it believes:
--   * the floor is black on the nest and source discs, white elsewhere;
--   * every tick, a robot in the nest (centre within nest radius + robot radius) is refilled;
--   * a robot whose battery reached 0 is killed, and its death tick recorded;
--   * a robot touches a source when its body overlaps the disc (centre distance < source radius +
--     robot radius); reaching the nest after touching one counts a trip for the last source
--     touched, per source and per robot;
--   * a source's discovery is the first touch of it by any robot (tick, robot).
--
-- Attributes of <loop_functions>:
--   nest="x,y,radius"                          metres
--   sources="A:x,y,radius;B:x,y,radius;..."    metres
--   timeseries_every="100"                     ticks between timeseries rows (0 = none)
--   robot_radius="0.085036758"                 optional, the foot-bot's
--   mining_led="255,255,0"                     optional: the LED colour a controller shows while
--       it heads to a source it means to mine; a robot showing it before it ever touched a source
--       must have been told where one is (range-and-bearing): it is listed in informed_robots.
--   decisions="off"                            optional: "series" watches the decisions of a
--       controller that publishes them (controllers/foraging.lua: globals decision_count and
--       decision) and adds them to the timeseries and the metrics; "log" also logs one line per
--       decision: "decision TICK ROBOT SOURCE WHY battery=B mu=M" (SOURCE: the source headed for,
--       "nest" when going home). Off, nothing is read from the controllers.
--
-- Metrics (post_experiment, written as metrics.json):
--   ticks, robots, trips_total, trips_per_source {name: n}, trips_per_robot {id: n},
--   trips_per_robot_mean, sources [{name, x, y, radius, trips, discovered_tick, discovered_by}],
--   discovered_count, first_discovery_tick, all_discovered_tick,
--   dead_robots [{robot, tick}], dead_count, dead_fraction,
--   first_touch_by_robot {id: {source, tick}}, informed_robots [id] (only with mining_led);
--   with decisions on: chose_greedy {name: n}, chose_epsilon {name: n} (picks at the nest),
--   started_found, started_message (explorers turned miners), battery_returns.
-- Timeseries columns: tick, trips_<name>..., trips_total, alive; with decisions on also
--   heading_<name>... (robots now heading for each source), chose_greedy_<name>...,
--   chose_epsilon_<name>..., battery_returns (cumulative).
-- A key that has no value is absent: an undiscovered source has no discovered_tick /
-- discovered_by; first_discovery_tick is absent when nothing was discovered, all_discovered_tick
-- when some source never was; a robot that never touched a source is absent from
-- first_touch_by_robot.
--
-- Arrays and objects carry a metatable {__jsontype = "array" | "object"} so that an empty one is
-- still written as [] or {} (a plain empty Lua table cannot tell).

local FOOTBOT_RADIUS = 0.085036758
local DEAD_CHARGE = 1e-9   -- a charge at or below this is an empty battery (float residue)

local cfg = nil            -- parsed attributes, see setup()
local robots_info = {}     -- by robot index: {touched, trips, first_touch, dead_tick, informed_tick}
local deaths = {}          -- {robot, tick} in order of death
local trips_total = 0
local watch = nil          -- decisions seen, when the decisions attribute asks for them

local function as_array(t) return setmetatable(t, { __jsontype = "array" }) end
local function as_object(t) return setmetatable(t, { __jsontype = "object" }) end

-- essaim's log() when the host offers one, print otherwise (plain-Lua tests).
local function say(text)
  local f = log or print
  f(text)
end

local function numbers(text, what)
  local out = {}
  for field in string.gmatch(text, "[^,]+") do
    local v = tonumber(field)
    if v == nil then error(what .. ": '" .. field .. "' is not a number", 0) end
    out[#out + 1] = v
  end
  return out
end

local NAMED_COLORS = {
  black = { 0, 0, 0 }, white = { 255, 255, 255 }, red = { 255, 0, 0 }, green = { 0, 255, 0 },
  blue = { 0, 0, 255 }, magenta = { 255, 0, 255 }, cyan = { 0, 255, 255 },
  yellow = { 255, 255, 0 }, orange = { 255, 140, 0 }, brown = { 165, 42, 42 },
  purple = { 160, 32, 240 },
}

local function parse_color(text)
  if text == nil or text == "" then return nil end
  local named = NAMED_COLORS[text]
  if named then return named end
  local c = numbers(text, "mining_led")
  if #c < 3 then error("mining_led: expected r,g,b or a colour name, got '" .. text .. "'", 0) end
  return { c[1], c[2], c[3] }
end

--- Reads the <loop_functions> attributes once (floor_color may run before init).
local function setup()
  if cfg then return cfg end
  local p = (experiment and experiment.params) or {}
  local c = { sources = {}, by_name = {} }
  local nest = numbers(p.nest or "0,0,0.5", "nest")
  if #nest ~= 3 then error("nest: expected x,y,radius", 0) end
  c.nest = { x = nest[1], y = nest[2], radius = nest[3] }
  for item in string.gmatch(p.sources or "", "[^;]+") do
    local name, rest = item:match("^%s*([^:%s]+)%s*:(.*)$")
    if name == nil then error("sources: expected NAME:x,y,radius, got '" .. item .. "'", 0) end
    local v = numbers(rest, "sources")
    if #v ~= 3 then error("sources: expected NAME:x,y,radius, got '" .. item .. "'", 0) end
    if c.by_name[name] then error("sources: '" .. name .. "' given twice", 0) end
    local s = { name = name, x = v[1], y = v[2], radius = v[3], trips = 0 }
    c.sources[#c.sources + 1] = s
    c.by_name[name] = s
  end
  c.every = math.tointeger(tonumber(p.timeseries_every or "100") or 100) or 100
  c.robot_radius = tonumber(p.robot_radius or "") or FOOTBOT_RADIUS
  c.mining_led = parse_color(p.mining_led)
  c.decisions = p.decisions or "off"
  if c.decisions ~= "off" and c.decisions ~= "series" and c.decisions ~= "log" then
    error("decisions: expected off, series or log, got '" .. c.decisions .. "'", 0)
  end
  cfg = c
  return c
end

local function inside(x, y, cx, cy, r)
  local dx, dy = x - cx, y - cy
  return dx * dx + dy * dy < r * r
end

function floor_color(x, y)
  local c = setup()
  if inside(x, y, c.nest.x, c.nest.y, c.nest.radius) then return 0, 0, 0 end
  for _, s in ipairs(c.sources) do
    if inside(x, y, s.x, s.y, s.radius) then return 0, 0, 0 end
  end
  return 255, 255, 255
end

-- Decisions ----------------------------------------------------------------------------------------

local REASONS = { "greedy", "epsilon", "found", "message", "battery", "trip" }

local function new_watch()
  local w = { seen = {}, heading = {}, count = {} }
  for _, why in ipairs(REASONS) do
    w.count[why] = { nest = 0 }
    for _, s in ipairs(cfg.sources) do w.count[why][s.name] = 0 end
  end
  return w
end

--- Name of the source nearest to (x, y) m, within twice its radius; nil when none is.
local function source_at(x, y)
  if x == nil or y == nil then return nil end
  local best, best_d2 = nil, math.huge
  for _, s in ipairs(cfg.sources) do
    local dx, dy = x - s.x, y - s.y
    local d2 = dx * dx + dy * dy
    if d2 < best_d2 and d2 <= 4 * s.radius * s.radius then best, best_d2 = s.name, d2 end
  end
  return best
end

--- Reads robot i's new decision, if it took one since last seen.
local function watch_robot(i, r)
  local n = r:lua_global("decision_count")
  if n == nil or n == watch.seen[i] then return end
  watch.seen[i] = n
  local d = r:lua_global("decision")
  if type(d) ~= "table" or d.why == nil then return end
  local name = source_at(d.x, d.y)
  watch.heading[i] = name
  local per = watch.count[d.why]
  if per then
    local key = name or "nest"
    per[key] = (per[key] or 0) + 1
  end
  if cfg.decisions == "log" then
    say(string.format("decision %d %s %s %s battery=%.1f mu=%.2f", d.tick or 0, r.id,
                      name or "nest", d.why, d.battery or -1, d.mu or -1))
  end
end

local function count_heading(name)
  local n = 0
  for i, r in ipairs(experiment.robots) do
    if watch.heading[i] == name and r:alive() then n = n + 1 end
  end
  return n
end

local function decision_columns(row)
  for _, s in ipairs(cfg.sources) do row[#row + 1] = { "heading_" .. s.name, count_heading(s.name) } end
  for _, why in ipairs({ "greedy", "epsilon" }) do
    for _, s in ipairs(cfg.sources) do
      row[#row + 1] = { "chose_" .. why .. "_" .. s.name, watch.count[why][s.name] }
    end
  end
  row[#row + 1] = { "battery_returns", watch.count.battery.nest }
end

local function decision_metrics(m)
  for _, why in ipairs({ "greedy", "epsilon" }) do
    local per = as_object({})
    for _, s in ipairs(cfg.sources) do per[s.name] = watch.count[why][s.name] end
    m["chose_" .. why] = per
  end
  m.started_found = watch.count.found.nest
  m.started_message = watch.count.message.nest
  m.battery_returns = watch.count.battery.nest
end

function init()
  cfg = nil
  setup()
  watch = cfg.decisions ~= "off" and new_watch() or nil
  robots_info, deaths, trips_total = {}, {}, 0
  for _, s in ipairs(cfg.sources) do
    s.trips, s.discovered_tick, s.discovered_by = 0, nil, nil
  end
  for i = 1, #experiment.robots do
    robots_info[i] = { trips = 0 }
  end
end

local function count_alive()
  local n = 0
  for _, r in ipairs(experiment.robots) do
    if r:alive() then n = n + 1 end
  end
  return n
end

local function timeseries_row(tick)
  local row = { { "tick", tick } }
  for _, s in ipairs(cfg.sources) do row[#row + 1] = { "trips_" .. s.name, s.trips } end
  row[#row + 1] = { "trips_total", trips_total }
  row[#row + 1] = { "alive", count_alive() }
  if watch then decision_columns(row) end
  experiment.timeseries(row)
end

local function shows_mining_led(r)
  local red, green, blue = r:led(1)
  local want = cfg.mining_led
  return red == want[1] and green == want[2] and blue == want[3]
end

--- The rules, applied after physics so that a dead robot does not act again and a refilled one
--- senses its full battery in the same tick.
function pre_step()
  setup()
  local tick = experiment.tick
  local R = cfg.robot_radius
  local nest = cfg.nest
  local sources = cfg.sources
  for i, r in ipairs(experiment.robots) do
    local info = robots_info[i]
    if info == nil then info = { trips = 0 }; robots_info[i] = info end
    if r:alive() then
      if r:battery() <= DEAD_CHARGE then
        r:kill()
        info.dead_tick = tick
        deaths[#deaths + 1] = { robot = r.id, tick = tick }
      else
        if cfg.mining_led and info.first_touch == nil and info.informed_tick == nil
           and shows_mining_led(r) then
          info.informed_tick = tick
        end
        if watch then watch_robot(i, r) end
        local x, y = r:position()
        -- inside() written out, and a numeric for: this runs for every robot every tick.
        for k = 1, #sources do
          local s = sources[k]
          local dx, dy, touch = x - s.x, y - s.y, s.radius + R
          if dx * dx + dy * dy < touch * touch then
            info.touched = s.name
            if info.first_touch == nil then info.first_touch = { source = s.name, tick = tick } end
            if s.discovered_tick == nil then s.discovered_tick, s.discovered_by = tick, r.id end
          end
        end
        local dx, dy, home = x - nest.x, y - nest.y, nest.radius + R
        if dx * dx + dy * dy < home * home then
          if info.touched then
            local s = cfg.by_name[info.touched]
            s.trips = s.trips + 1
            info.trips = info.trips + 1
            trips_total = trips_total + 1
            info.touched = nil
          end
          r:set_battery(1)
        end
      end
    end
  end
  if cfg.every > 0 and tick % cfg.every == 0 then timeseries_row(tick) end
end

local function round(v, digits)
  local m = 10 ^ digits
  return math.floor(v * m + 0.5) / m
end

--- The metrics table (see the header) and a short summary in the log.
function post_experiment()
  local robots = experiment.robots
  local n = #robots
  local m = {
    ticks = experiment.tick,
    robots = n,
    trips_total = trips_total,
    trips_per_source = as_object({}),
    trips_per_robot = as_object({}),
    trips_per_robot_mean = n > 0 and round(trips_total / n, 4) or 0,
    sources = as_array({}),
    dead_robots = as_array({}),
    dead_count = #deaths,
    dead_fraction = n > 0 and round(#deaths / n, 4) or 0,
    first_touch_by_robot = as_object({}),
  }
  local discovered, first, last = 0, nil, nil
  for _, s in ipairs(cfg.sources) do
    m.trips_per_source[s.name] = s.trips
    m.sources[#m.sources + 1] = as_object({
      name = s.name, x = s.x, y = s.y, radius = s.radius, trips = s.trips,
      discovered_tick = s.discovered_tick, discovered_by = s.discovered_by,
    })
    if s.discovered_tick then
      discovered = discovered + 1
      if first == nil or s.discovered_tick < first then first = s.discovered_tick end
      if last == nil or s.discovered_tick > last then last = s.discovered_tick end
    end
  end
  m.discovered_count = discovered
  m.first_discovery_tick = first
  if discovered == #cfg.sources and discovered > 0 then m.all_discovered_tick = last end
  for i, r in ipairs(robots) do
    local info = robots_info[i]
    m.trips_per_robot[r.id] = info.trips
    if info.first_touch then
      m.first_touch_by_robot[r.id] = as_object({ source = info.first_touch.source,
                                                 tick = info.first_touch.tick })
    end
  end
  for _, d in ipairs(deaths) do
    m.dead_robots[#m.dead_robots + 1] = as_object({ robot = d.robot, tick = d.tick })
  end
  if watch then decision_metrics(m) end
  if cfg.mining_led then
    m.informed_robots = as_array({})
    for i, r in ipairs(robots) do
      if robots_info[i].informed_tick then m.informed_robots[#m.informed_robots + 1] = r.id end
    end
  end

  -- summary
  local found = {}
  for _, s in ipairs(cfg.sources) do
    if s.discovered_tick then
      found[#found + 1] = string.format("%s@%d by %s", s.name, s.discovered_tick, s.discovered_by)
    else
      found[#found + 1] = s.name .. " not found"
    end
  end
  say(string.format("foraging: %d/%d sources discovered: %s", discovered, #cfg.sources,
                    table.concat(found, ", ")))
  local per = {}
  for _, s in ipairs(cfg.sources) do per[#per + 1] = s.name .. "=" .. s.trips end
  say(string.format("foraging: %d trips (%s), %.2f per robot", trips_total,
                    table.concat(per, " "), m.trips_per_robot_mean))
  if #deaths > 0 then
    local dead = {}
    for _, d in ipairs(deaths) do dead[#dead + 1] = d.robot .. "@" .. d.tick end
    say(string.format("foraging: %d/%d robots ran out of battery: %s", #deaths, n,
                      table.concat(dead, " ")))
  else
    say(string.format("foraging: no robot ran out of battery (%d robots)", n))
  end
  if m.informed_robots then
    say(string.format("foraging: %d robots mined a source they were told about before touching one",
                      #m.informed_robots))
  end
  return m
end

function reset()
  init()
end
