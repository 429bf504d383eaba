-- A deliberately small stand-in for the simulator, to run the foraging controller and its loop
-- functions end to end in plain Lua before (and independently of) the C++ core.
--
-- It follows the spec where the controller depends on it: the step
-- order (act, physics, battery, media, loop pre_step, sense + control, loop post_step), one-step
-- latency of wheels/LEDs/RAB payloads, the proximity ring's 24 rays and reading law, the rotating
-- distance scanner (6 rays per sensor per tick, -1/-2 codes, cm from the body surface), the 8
-- binary base-ground sensors, RAB within the sender's range with occlusions, a time-discharged
-- battery. Physics is kinematic: a robot moves along its tick-start heading, then overlaps with
-- walls, cylinders and other robots are pushed apart. Good enough to exercise behaviour, not to
-- measure it.
local M = {}

local R = 0.085036758          -- foot-bot radius (m)
local AXIS = 14                -- cm
local pi = math.pi

local COLORS = {
  black = { 0, 0, 0 }, white = { 255, 255, 255 }, red = { 255, 0, 0 }, green = { 0, 255, 0 },
  blue = { 0, 0, 255 }, magenta = { 255, 0, 255 }, cyan = { 0, 255, 255 },
  yellow = { 255, 255, 0 }, orange = { 255, 140, 0 }, brown = { 165, 42, 42 },
  purple = { 160, 32, 240 },
}

local GROUND = { { 0.08, 0 }, { 0.042, 0.065 }, { 0, 0.08 }, { -0.042, 0.065 }, { -0.08, 0 },
                 { -0.042, -0.065 }, { 0, -0.08 }, { 0.042, -0.065 } }

-- drand48-style generator with robot.random's interface
local function make_rng(seed)
  local state = (seed * 2654435761 + 12345) & 0xFFFFFFFFFFFF
  local r = {}
  local function u01()
    state = (state * 0x5DEECE66D + 0xB) & 0xFFFFFFFFFFFF
    return state / 0x1000000000000
  end
  function r.uniform(a, b)
    local u = u01()
    if a == nil then return u end
    if b == nil then return u * a end
    return a + u * (b - a)
  end
  function r.bernoulli(p) return u01() < (p or 0.5) end
  return r
end
M.make_rng = make_rng

-- Ray from (ox, oy) along unit (dx, dy): distance to a circle, or nil.
local function ray_circle(ox, oy, dx, dy, cx, cy, r, len)
  local fx, fy = ox - cx, oy - cy
  local c = fx * fx + fy * fy - r * r
  if c <= 0 then return 0 end
  local b = fx * dx + fy * dy
  if b > 0 then return nil end
  local disc = b * b - c
  if disc < 0 then return nil end
  local t = -b - math.sqrt(disc)
  if t < 0 or t > len then return nil end
  return t
end

local World = {}
World.__index = World

--- opts: half (inner half-size of the square arena, m), cylinders {{x, y, r}},
--- robots {{id, x, y, yaw}}, controller (path), params (strings), loop (path),
--- loop_params (strings), tps (10), rab_range (3), battery_delta (0.002), seed.
function M.new(opts)
  local w = setmetatable({}, World)
  w.half = opts.half or 5
  w.cylinders = opts.cylinders or {}
  w.tps = opts.tps or 10
  w.dt = 1 / w.tps
  w.tick = 0
  w.rab_range = opts.rab_range or 3
  w.delta = opts.battery_delta or 0.002
  w.logs = {}
  w.rows = {}
  w.robots = {}
  w.errors = {}

  -- loop functions
  w.experiment = {
    tick = 0, ticks_per_second = w.tps, length_ticks = opts.length or 0, seed = opts.seed or 1,
    params = opts.loop_params or {},
    arena = { size_x = 2 * w.half, size_y = 2 * w.half, center_x = 0, center_y = 0 },
    robots = {}, random = make_rng(opts.seed or 1), output_dir = ".",
  }
  w.experiment.timeseries = function(row)
    local copy = {}
    for i, kv in ipairs(row) do copy[i] = { kv[1], kv[2] } end
    w.rows[#w.rows + 1] = copy
  end
  local function log_fn(...)
    local parts = {}
    for i, v in ipairs({ ... }) do parts[i] = tostring(v) end
    w.logs[#w.logs + 1] = table.concat(parts)
  end
  if opts.loop then
    w.loop = setmetatable({ experiment = w.experiment, log = log_fn }, { __index = _G })
    assert(loadfile(opts.loop, "t", w.loop))()
  end

  for i, spec in ipairs(opts.robots) do
    local rb = {
      index = i, id = spec.id or ("fb" .. (i - 1)), x = spec.x, y = spec.y, yaw = spec.yaw or 0,
      vl = 0, vr = 0, cmd_l = 0, cmd_r = 0, charge = 1, alive = true, ok = true,
      led = { 0, 0, 0 }, cmd_led = { 0, 0, 0 },
      payload = { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 }, cmd_payload = nil,
      scan_mode = "off", scan_angle = 0, scan_prev = 0, scan_speed = 0,
    }
    w.robots[i] = rb
    local handle = { id = rb.id, index = i }
    function handle.position() return rb.x, rb.y end
    function handle.heading() return rb.yaw end
    function handle.set_pose(_, x, y, yaw) rb.x, rb.y, rb.yaw, rb.vl, rb.vr = x, y, yaw, 0, 0 end
    function handle.battery() return rb.charge end
    function handle.set_battery(_, c) rb.charge = c end
    function handle.alive() return rb.alive end
    function handle.kill() rb.alive = false; rb.vl, rb.vr, rb.cmd_l, rb.cmd_r = 0, 0, 0, 0 end
    function handle.led() return rb.led[1], rb.led[2], rb.led[3] end
    function handle.controller_ok() return rb.ok end
    w.experiment.robots[i] = handle
    w:make_controller(rb, opts.controller, opts.params or {}, (opts.seed or 1) * 1000 + i, log_fn)
  end

  for _, rb in ipairs(w.robots) do w:call(rb, "init") end
  if w.loop and w.loop.init then w.loop.init() end
  return w
end

function World:make_controller(rb, path, params, seed, log_fn)
  local robot = { id = rb.id, random = make_rng(seed), params = {} }
  for k, v in pairs(params) do robot.params[k] = v end
  robot.params.script = path
  robot.wheels = { axis_length = AXIS, velocity_left = 0, velocity_right = 0 }
  function robot.wheels.set_velocity(l, r) rb.cmd_l, rb.cmd_r = l, r end
  robot.leds = {}
  function robot.leds.set_all_colors(name, g, b)
    if g ~= nil then rb.cmd_led = { name, g, b } else rb.cmd_led = assert(COLORS[name], name) end
  end
  robot.range_and_bearing = {}
  function robot.range_and_bearing.set_data(data)
    assert(#data == 10, "set_data needs 10 bytes")
    local copy = {}
    for i = 1, 10 do
      local v = data[i]
      assert(type(v) == "number", "byte " .. i .. " is not a number")
      copy[i] = math.tointeger(v) or math.floor(v)
    end
    rb.cmd_payload = copy
  end
  function robot.range_and_bearing.clear_data() rb.cmd_payload = { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 } end
  robot.distance_scanner = { short_range = {}, long_range = {} }
  function robot.distance_scanner.enable() rb.scan_mode = "position" end
  function robot.distance_scanner.disable() rb.scan_mode = "off" end
  function robot.distance_scanner.set_rpm(rpm) rb.scan_mode = "speed"; rb.scan_speed = rpm * pi / 30 end
  function robot.distance_scanner.set_angle(a) rb.scan_mode = "position"; rb.scan_angle = a end
  robot.proximity = {}
  for i = 1, 24 do
    local a = pi / 24 + (i - 1) * pi / 12
    if a > pi then a = a - 2 * pi end
    robot.proximity[i] = { value = 0, angle = a }
  end
  robot.base_ground = {}
  for i = 1, 8 do robot.base_ground[i] = { value = 1, offset = { x = GROUND[i][1] * 100, y = GROUND[i][2] * 100 } } end
  robot.battery = { available_charge = 1, time_left = math.huge }
  robot.positioning = {}
  rb.robot = robot
  self:write_pose(rb)
  rb.env = setmetatable({ robot = robot, log = log_fn, logerr = log_fn }, { __index = _G })
  local chunk = assert(loadfile(path, "t", rb.env))
  chunk()
end

function World:write_pose(rb)
  local yaw = rb.yaw
  rb.robot.positioning.position = { x = rb.x, y = rb.y, z = 0 }
  rb.robot.positioning.orientation = {
    w = math.cos(yaw / 2), x = 0, y = 0, z = math.sin(yaw / 2),
    toeulerangles = function() return math.atan(math.sin(yaw), math.cos(yaw)), 0, 0 end,
  }
end

function World:call(rb, name)
  if not rb.ok then return end
  local f = rb.env[name]
  if f == nil then return end
  local ok, err = xpcall(f, debug.traceback)
  if not ok then
    rb.ok = false
    self.errors[#self.errors + 1] = rb.id .. " tick " .. self.tick .. ": " .. tostring(err)
  end
end

-- Nearby circles (cylinders and other robots) for rays of up to `reach` m from rb.
function World:nearby(rb, reach)
  local out = {}
  for _, c in ipairs(self.cylinders) do
    local dx, dy = c[1] - rb.x, c[2] - rb.y
    local lim = reach + c[3]
    if dx * dx + dy * dy < lim * lim then out[#out + 1] = { c[1], c[2], c[3], nil } end
  end
  for _, o in ipairs(self.robots) do
    if o ~= rb then
      local dx, dy = o.x - rb.x, o.y - rb.y
      local lim = reach + R
      if dx * dx + dy * dy < lim * lim then out[#out + 1] = { o.x, o.y, R, o } end
    end
  end
  return out
end

-- Closest hit along a ray among `objs` and the walls: distance (or nil), object (nil for walls).
function World:cast(ox, oy, dx, dy, len, objs)
  local best, what = nil, nil
  local h = self.half
  local function wall(t)
    if t >= 0 and t <= len and (best == nil or t < best) then best, what = t, "wall" end
  end
  if dx > 1e-12 then wall((h - ox) / dx) elseif dx < -1e-12 then wall((-h - ox) / dx) end
  if dy > 1e-12 then wall((h - oy) / dy) elseif dy < -1e-12 then wall((-h - oy) / dy) end
  for _, c in ipairs(objs) do
    local t = ray_circle(ox, oy, dx, dy, c[1], c[2], c[3], len)
    if t and (best == nil or t < best) then best, what = t, c[4] or "cylinder" end
  end
  return best, what
end

function World:act()
  for _, rb in ipairs(self.robots) do
    if rb.alive then
      rb.vl, rb.vr = rb.cmd_l, rb.cmd_r
    else
      rb.vl, rb.vr = 0, 0
    end
    rb.led = rb.cmd_led
    if rb.cmd_payload then rb.payload = rb.cmd_payload; rb.cmd_payload = nil end
  end
end

function World:physics()
  local dt = self.dt
  for _, rb in ipairs(self.robots) do
    local v = (rb.vl + rb.vr) / 200
    local omega = (rb.vr - rb.vl) / AXIS
    rb.x = rb.x + v * math.cos(rb.yaw) * dt
    rb.y = rb.y + v * math.sin(rb.yaw) * dt
    rb.yaw = rb.yaw + omega * dt
  end
  for _ = 1, 3 do
    for i, rb in ipairs(self.robots) do
      for _, c in ipairs(self.cylinders) do
        local dx, dy = rb.x - c[1], rb.y - c[2]
        local d = math.sqrt(dx * dx + dy * dy)
        local min = R + c[3]
        if d < min and d > 1e-9 then
          rb.x, rb.y = c[1] + dx / d * min, c[2] + dy / d * min
        end
      end
      for j = i + 1, #self.robots do
        local o = self.robots[j]
        local dx, dy = rb.x - o.x, rb.y - o.y
        local d = math.sqrt(dx * dx + dy * dy)
        if d < 2 * R and d > 1e-9 then
          local push = (2 * R - d) / 2
          rb.x, rb.y = rb.x + dx / d * push, rb.y + dy / d * push
          o.x, o.y = o.x - dx / d * push, o.y - dy / d * push
        end
      end
      local lim = self.half - R
      if rb.x > lim then rb.x = lim elseif rb.x < -lim then rb.x = -lim end
      if rb.y > lim then rb.y = lim elseif rb.y < -lim then rb.y = -lim end
    end
  end
  for _, rb in ipairs(self.robots) do
    rb.charge = math.max(0, rb.charge - self.delta)
    if rb.scan_mode == "speed" then
      rb.scan_angle = (rb.scan_angle + rb.scan_speed * dt) % (2 * pi)
    end
  end
end

local function wrap(a) return (a + pi) % (2 * pi) - pi end

function World:sense(rb)
  local robot = rb.robot
  self:write_pose(rb)
  robot.battery.available_charge = rb.charge
  robot.wheels.velocity_left, robot.wheels.velocity_right = rb.vl, rb.vr
  -- proximity
  local objs = self:nearby(rb, 1.6)
  for i = 1, 24 do
    local a = rb.yaw + robot.proximity[i].angle
    local dx, dy = math.cos(a), math.sin(a)
    local d = self:cast(rb.x + R * dx, rb.y + R * dy, dx, dy, 0.1, objs)
    local v = 0
    if d then
      if d < 0.009889556 then v = 1 else v = 0.0100527 / (d + 0.000163144) end
    end
    robot.proximity[i].value = v
  end
  -- distance scanner
  local short, long = {}, {}
  if rb.scan_mode ~= "off" then
    local angles
    if rb.scan_mode == "speed" then
      local span = (rb.scan_angle - rb.scan_prev) % (2 * pi)
      angles = {}
      for k = 0, 5 do angles[#angles + 1] = rb.scan_prev + k * span / 6 end
    else
      angles = { rb.scan_angle }
    end
    rb.scan_prev = rb.scan_angle
    local function ray(rel, len, min, out)
      local a = rb.yaw + rel
      local dx, dy = math.cos(a), math.sin(a)
      local d = self:cast(rb.x + R * dx, rb.y + R * dy, dx, dy, len, objs)
      local v = -2
      if d then v = (d <= min) and -1 or d * 100 end
      out[#out + 1] = { angle = wrap(rel), distance = v }
    end
    for _, th in ipairs(angles) do
      ray(th, 0.26, 0, short); ray(th + pi, 0.26, 0, short)
      ray(th + pi / 2, 1.42, 0.12, long); ray(th - pi / 2, 1.42, 0.12, long)
    end
    table.sort(short, function(p, q) return p.angle < q.angle end)
    table.sort(long, function(p, q) return p.angle < q.angle end)
  end
  robot.distance_scanner.short_range, robot.distance_scanner.long_range = short, long
  -- ground
  local c, s = math.cos(rb.yaw), math.sin(rb.yaw)
  for i = 1, 8 do
    local ox, oy = GROUND[i][1], GROUND[i][2]
    local px, py = rb.x + c * ox - s * oy, rb.y + s * ox + c * oy
    local value = 1
    if self.loop and self.loop.floor_color then
      local r, g, b = self.loop.floor_color(px, py)
      local grey = (0.299 * r + 0.587 * g + 0.114 * b) / 255
      value = grey < 0.5 and 0 or 1
    end
    robot.base_ground[i].value = value
  end
  -- range and bearing (messages computed in media())
  local rab = robot.range_and_bearing
  for i = #rab, 1, -1 do rab[i] = nil end
  for i, m in ipairs(rb.inbox or {}) do rab[i] = m end
end

function World:media()
  for _, rb in ipairs(self.robots) do rb.inbox = {} end
  for i, a in ipairs(self.robots) do
    for j = i + 1, #self.robots do
      local b = self.robots[j]
      local dx, dy = b.x - a.x, b.y - a.y
      local d = math.sqrt(dx * dx + dy * dy)
      if d < self.rab_range and d > 1e-9 then
        local objs = self:nearby(a, d)
        local _, hit = self:cast(a.x, a.y, dx / d, dy / d, d, objs)
        if hit == b or hit == nil then
          local function deliver(from, to, vx, vy)
            local data = {}
            for k = 1, 10 do data[k] = from.payload[k] end
            to.inbox[#to.inbox + 1] = { range = d * 100,
              horizontal_bearing = wrap(math.atan(vy, vx) - to.yaw), vertical_bearing = 0,
              data = data, _from = from.index }
          end
          if b.alive then deliver(b, a, dx, dy) end
          if a.alive then deliver(a, b, -dx, -dy) end
        end
      end
    end
  end
  for _, rb in ipairs(self.robots) do
    table.sort(rb.inbox, function(p, q) return p._from < q._from end)
  end
end

function World:step()
  self.tick = self.tick + 1
  self.experiment.tick = self.tick
  self:act()
  self:physics()
  self:media()
  if self.loop and self.loop.pre_step then self.loop.pre_step() end
  for _, rb in ipairs(self.robots) do
    if rb.alive then
      self:sense(rb)
      self:call(rb, "step")
    end
  end
  if self.loop and self.loop.post_step then self.loop.post_step() end
end

function World:run(ticks)
  for _ = 1, ticks do self:step() end
  local metrics = nil
  if self.loop and self.loop.post_experiment then metrics = self.loop.post_experiment() end
  return metrics
end

--- Deterministic placement of n cylinders (radius r) clear of the given discs by `gap` m.
function M.scatter(n, r, half, discs, gap, seed)
  local rng = make_rng(seed or 7)
  local out = {}
  local tries = 0
  while #out < n and tries < 100000 do
    tries = tries + 1
    local x = rng.uniform(-half + r + gap, half - r - gap)
    local y = rng.uniform(-half + r + gap, half - r - gap)
    local ok = true
    for _, d in ipairs(discs) do
      if (x - d[1]) ^ 2 + (y - d[2]) ^ 2 < (d[3] + r + gap) ^ 2 then ok = false; break end
    end
    if ok then
      for _, c in ipairs(out) do
        if (x - c[1]) ^ 2 + (y - c[2]) ^ 2 < (2 * r + gap) ^ 2 then ok = false; break end
      end
    end
    if ok then out[#out + 1] = { x, y, r } end
  end
  return out
end

return M
