-- Loop functions of the object-clustering experiment (arenas/clustering.argos): foot-bots
-- carry LED cylinders into a black zone. Uses the loop-function API of
-- docs/loop-functions.md the way ARGoS loop functions use CSpace:
--   * the floor is black inside the zone (floor_color);
--   * init() scatters the cylinders (add_entity) at random in a ring around the zone, each
--     with one red LED on top, away from robots and from each other;
--   * every tick, a cylinder whose centre is in the zone turns blue, one pushed back out turns
--     red again (set_led_color): the robots' cameras see it from their next sense, and the
--     controller lets go of a load that turned blue;
--   * every `every` ticks a timeseries row: cylinders in the zone, and the deliveries the
--     robots counted themselves (their global `deliveries`, read with r:lua_global).
--
-- Children of <loop_functions> (experiment.params.<child>.<attribute>):
--   <zone x="0" y="0" radius="0.5"/>                                 m
--   <cylinders count="12" radius="0.05" height="0.1" mass="0.2" min_distance="0.9" max_distance="1.7"/>
--   <output every="50"/>                                             ticks between timeseries rows
--
-- Metrics (post_experiment → metrics.json): cylinders, in_zone (at the end), first_delivery_tick,
-- all_delivered_tick (absent unless all arrived), delivery_ticks [tick each cylinder first
-- arrived, in arrival order], robot_deliveries (sum of the controllers' counters).

local P = experiment.params
local zone = {x = tonumber(P.zone.x), y = tonumber(P.zone.y), r = tonumber(P.zone.radius)}
local cyl = {count = tonumber(P.cylinders.count), radius = tonumber(P.cylinders.radius),
             height = tonumber(P.cylinders.height), mass = tonumber(P.cylinders.mass),
             min_d = tonumber(P.cylinders.min_distance), max_d = tonumber(P.cylinders.max_distance)}
local every = tonumber(P.output and P.output.every or "50")

local arrived = {}          -- id → true while in the zone
local ever = {}             -- id → true once it first arrived
local delivery_ticks = {}
local all_delivered_tick = nil

local function in_zone(x, y) return (x - zone.x) ^ 2 + (y - zone.y) ^ 2 < zone.r ^ 2 end

function floor_color(x, y)
  if in_zone(x, y) then return "black" end
  return "white"
end

-- A spot in the ring, clear of every entity placed so far (tries a few times, then takes it).
local function free_spot()
  local x, y
  for _ = 1, 100 do
    local a = experiment.random.uniform(0, 2 * math.pi)
    local d = experiment.random.uniform(cyl.min_d, cyl.max_d)
    x, y = zone.x + d * math.cos(a), zone.y + d * math.sin(a)
    local clear = true
    for _, e in ipairs(experiment.entities()) do
      local ex, ey = e:position()
      if (ex - x) ^ 2 + (ey - y) ^ 2 < 0.25 ^ 2 then clear = false break end
    end
    if clear then break end
  end
  return x, y
end

function init()
  for i = 1, cyl.count do
    local x, y = free_spot()
    experiment.add_entity("cylinder", {
      id = "load" .. i, position = {x, y, 0}, radius = cyl.radius, height = cyl.height,
      movable = true, mass = cyl.mass, medium = "leds",
      leds = {{offset = {0, 0, cyl.height}, anchor = "origin", color = "red"}}})
  end
end

function post_step()
  local count = 0
  for _, c in ipairs(experiment.entities("cylinder")) do
    local x, y = c:position()
    local inside = in_zone(x, y)
    if inside and not arrived[c.id] then
      c:set_led_color("blue")
      if not ever[c.id] then delivery_ticks[#delivery_ticks + 1] = experiment.tick end
      ever[c.id] = true
    elseif not inside and arrived[c.id] then
      c:set_led_color("red")
    end
    arrived[c.id] = inside or nil
    if inside then count = count + 1 end
  end
  if count == cyl.count and not all_delivered_tick then all_delivered_tick = experiment.tick end
  if every > 0 and experiment.tick % every == 0 then
    local counted = 0
    for _, r in ipairs(experiment.robots) do counted = counted + (r:lua_global("deliveries") or 0) end
    experiment.timeseries({{"tick", experiment.tick}, {"in_zone", count}, {"robot_deliveries", counted}})
  end
end

function is_experiment_finished() return all_delivered_tick ~= nil end

function post_experiment()
  local in_zone_now, counted = 0, 0
  for _ in pairs(arrived) do in_zone_now = in_zone_now + 1 end
  for _, r in ipairs(experiment.robots) do counted = counted + (r:lua_global("deliveries") or 0) end
  return {cylinders = cyl.count, in_zone = in_zone_now, first_delivery_tick = delivery_ticks[1],
          all_delivered_tick = all_delivered_tick,
          delivery_ticks = setmetatable(delivery_ticks, {__jsontype = "array"}),
          robot_deliveries = counted}
end
