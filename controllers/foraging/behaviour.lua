-- The foraging behaviour (report chapter 6): a state machine over percepts, returning actions.
--
-- It never touches `robot`: foraging.lua turns the sensors into a percept table and applies the
-- returned actions, so the whole behaviour runs in plain Lua tests too.
--
-- Percepts (units of the report: cm, rad, battery units 0..100):
--   tick, x, y, yaw, battery,
--   ground     = array of 8 base-ground values (0 black, 1 white),
--   proximity  = array of 24 {value, angle},
--   short, long = distance-scanner readings, arrays of {angle, distance} (cm, -1, -2),
--   messages   = array of received payloads (arrays of bytes).
-- Actions: { left, right (cm/s), color (LED colour name), message (10 bytes, or nil) }.
--
-- States: "explore" (gas-like walk, report 6.1.2) and "mine" (trips between a known source and
-- the nest, 6.1.3). Orthogonal to both, `back_for_battery` sends the robot home (6.2.2).
local motion = require "foraging.motion"
local scanner = require "foraging.scanner"
local geometry = require "foraging.geometry"
local comm = require "foraging.comm"
local sources = require "foraging.sources"
local battery = require "foraging.battery"
local ground = require "foraging.ground"

local M = {}

local pi = math.pi

M.COLORS = {
  explore = "green",      -- exploring
  to_source = "yellow",   -- mining, on the way to a source
  to_nest = "orange",     -- mining, on the way back to the nest
  battery = "red",        -- going home because of the battery
}

--- New behaviour state. `random` offers uniform() and uniform(a, b) like robot.random.
function M.new(cfg, random)
  local st = {
    cfg = cfg,
    random = random,
    mode = "explore",
    sources = {},            -- known sources {x, y, trips, spent, score}
    target = nil,            -- index of the source being mined
    going_home = false,      -- mine: heading to the nest (loaded, or to refill before a trip)
    back_for_battery = false,
    mu = cfg.INIT_BATT_SEC,  -- battery safety coefficient
    turn_to = nil,           -- gas-like walk: world heading of the rebound in progress
    speed = motion.new_speed_state(cfg.BASE_SPEED),
    long = scanner.new(cfg.DIR_NUMBER, cfg.FREE_DISTANCE),
    short = scanner.new(cfg.DIR_NUMBER, cfg.FREE_DISTANCE),
    expl = scanner.new(cfg.EXPL_DIR_NUMBER, cfg.FREE_DISTANCE),
    battery_prev = nil,      -- battery at the previous step
    battery_leave = 100,     -- battery when the robot last left the nest
    away = false,            -- left the nest since the last return
    trips = 0,               -- trips this robot believes it made
    decisions = 0,           -- decisions taken so far (see note_decision)
    why = nil,               -- reason of the last decision
  }
  for _, s in ipairs(cfg.known_sources) do
    sources.add(st.sources, s[1], s[2], cfg.ORGN_SRC_DST, cfg.INIT_SCORE)
  end
  if #st.sources > 0 then
    -- Omniscient mode (report 7.1.1): mine the known sources from the first step.
    st.mode = "mine"
    local why
    st.target, why = sources.choose(st.sources, cfg.EPSILONGREED, random.uniform)
    M.note_decision(st, why)
  end
  return st
end

--- Records a decision and its reason, so that the controller can show it to the loop functions
--- (how robots pick their sources is then seen, not guessed). Reasons: "greedy" and "epsilon"
--- (the epsilon-greedy draw at the nest), "found" (a source of its own: mine), "message" (a
--- source heard of: mine), "battery" (home to refill, the source given up), "trip" (reached the
--- source, home with the load). The target is st.target for the first two, the nest otherwise.
function M.note_decision(st, why)
  st.decisions = st.decisions + 1
  st.why = why
end

-- Movement -----------------------------------------------------------------------------------------

-- Towards (gx, gy): intermediate avoidance when the short range sees an obstacle in front closer
-- than HIT_DISTANCE (4.5), otherwise greedy avoidance with the long range (4.3) and the
-- convergence law (4.2). The goal counts as reached `reach` cm from (gx, gy): obstacles beyond
-- that (robots crowding the nest, say) do not turn the robot away.
local function go_to(st, p, gx, gy, reach, speed)
  local cfg = st.cfg
  local near, near_angle = scanner.closest(st.short, p.yaw, cfg.AVOID_CONE)
  if near < cfg.HIT_DISTANCE then
    return motion.avoidance(near_angle, motion.closeness(near, cfg.HIT_DISTANCE), speed,
                            cfg.OBSTACLE_DIRECTION_DEPENDANCE, cfg.OBSTACLE_PROXIMITY_DEPENDANCE)
  end
  local goal_dir = geometry.direction(p.x, p.y, gx, gy)
  local goal_dist = math.max(geometry.distance(p.x, p.y, gx, gy) - reach, 0)
  local dir = scanner.best_direction(st.long, goal_dir, goal_dist)
  return motion.convergence(geometry.wrap(dir - p.yaw), speed, cfg.CONVERGENCE)
end

-- Gas-like walk (annex 6.B): straight ahead; an obstacle in front closer than HIT_DISTANCE makes
-- the robot rebound like a particle off a wall facing it: from relative direction theta the new
-- heading is pi + 2 theta away from the current one, reached with sharp turns (EXPL_CONV).
function M.rebound(theta)
  return geometry.wrap(pi + 2 * theta)
end

local function gas_like(st, p, speed)
  local cfg = st.cfg
  if st.turn_to == nil then
    local near, near_angle = scanner.closest(st.expl, p.yaw, pi / 2)
    if near < cfg.HIT_DISTANCE then
      st.turn_to = geometry.wrap(p.yaw + M.rebound(near_angle))
    end
  end
  if st.turn_to ~= nil then
    local rel = geometry.wrap(st.turn_to - p.yaw)
    if math.abs(rel) >= cfg.TURN_TOLERANCE then
      return motion.convergence(rel, speed, cfg.EXPL_CONV)
    end
    st.turn_to = nil
  end
  return speed, speed
end

-- Knowledge -----------------------------------------------------------------------------------------

-- Records the source under the robot if it is new (listing 6.3). Returns true when it was new.
local function detect_source(st, p, place, inside)
  if place == "source" and inside then
    return sources.add(st.sources, p.x, p.y, st.cfg.ORGN_SRC_DST, st.cfg.INIT_SCORE) ~= nil
  end
  return false
end

-- Decodes received messages, keeps the original sources (listings 6.16, 6.17).
-- Returns true when at least one new source was learnt.
local function listen(st, messages)
  local got = false
  for i = 1, #messages do
    local x, y = comm.decode(messages[i])
    if x ~= nil and sources.add(st.sources, x, y, st.cfg.ORGN_SRC_DST, st.cfg.INIT_SCORE) then
      got = true
    end
  end
  return got
end

-- States --------------------------------------------------------------------------------------------

local function start_mining(st, why)
  st.mode = "mine"
  st.going_home = true      -- refill at the nest, then pick a source (listing 6.6)
  st.turn_to = nil
  M.note_decision(st, why)
end

local function explore(st, p, found, got, speed)
  if found then
    start_mining(st, "found")
  elseif got and st.random.uniform() < st.cfg.MINE_PROB_WHEN_SRC_RECVD then
    start_mining(st, "message")
  end
  if st.mode == "explore" and not st.back_for_battery then
    return gas_like(st, p, speed)
  end
  return go_to(st, p, st.cfg.nest_x, st.cfg.nest_y, st.cfg.nest_radius, speed)
end

local function mine(st, p, place, speed)
  local cfg = st.cfg
  local spent = st.battery_leave - p.battery
  local src = st.target and st.sources[st.target]
  if place == "source" and not st.going_home and src ~= nil
     and geometry.distance(p.x, p.y, src.x, src.y) <= 2 * cfg.ORGN_SRC_DST then
    -- reached the source being mined: a trip, score it, head home (listing 6.9)
    sources.record_trip(src, spent)
    st.trips = st.trips + 1
    st.going_home = true
    M.note_decision(st, "trip")
  elseif place == "nest" and st.going_home then
    -- back home: choose the next source (epsilon-greedy)
    local why
    st.target, why = sources.choose(st.sources, cfg.EPSILONGREED, st.random.uniform)
    st.going_home = st.target == nil
    if why then M.note_decision(st, why) end
  elseif st.back_for_battery and not st.going_home then
    -- the battery forces the robot home before it reached the source: a trip for nothing
    if src ~= nil then sources.record_abort(src) end
    st.going_home = true
    M.note_decision(st, "battery")
  end
  if st.going_home or st.target == nil then
    return go_to(st, p, cfg.nest_x, cfg.nest_y, cfg.nest_radius, speed)
  end
  local target = st.sources[st.target]
  return go_to(st, p, target.x, target.y, 0, speed)
end

local function color_of(st)
  if st.back_for_battery then return M.COLORS.battery end
  if st.mode == "explore" then return M.COLORS.explore end
  if st.going_home then return M.COLORS.to_nest end
  return M.COLORS.to_source
end

-- Battery bookkeeping at the nest and away from it (report 6.2.2, listings 6.2, 6.13).
--
-- mu is judged at every return to the nest, as the report's text has it ("constamment
-- réévalué": lower after a surplus, higher after a deficit), not only after the battery forced
-- the return, as its listing 6.13 does: a robot that only mines the near source never runs its
-- battery low, so its mu would stay at the too cautious INIT_BATT_SEC and send it home halfway
-- to every far source it tries (the far source then scores nothing).
local function track_battery(st, p, place, dist_nest)
  local cfg = st.cfg
  if place == "nest" then
    if st.back_for_battery or st.away then
      -- The nest may already have refilled the battery this step: judge the return on the
      -- lower of this step's and the previous step's readings.
      local leftover = math.min(p.battery, st.battery_prev or p.battery)
      st.mu = battery.update_safety(st.mu, leftover, cfg.IDEAL_NEST_BATT,
                                    cfg.BATT_GAIN_DOWN, cfg.BATT_GAIN_UP, cfg.MIN_SAFETY)
      st.back_for_battery = false
    end
    st.battery_leave = p.battery
    st.away = false
    return
  end
  if dist_nest > cfg.nest_radius + cfg.SOURCE_MARGIN then
    st.away = true           -- clear of the nest: the next arrival is a return
  end
  local was = st.back_for_battery
  st.back_for_battery = was
    or battery.must_go_home(p.battery, st.mu, cfg.BATT_BY_STEP, dist_nest, cfg.BASE_SPEED,
                            cfg.IDEAL_NEST_BATT)
  -- a miner's return is noted where its source is given up (mine)
  if st.back_for_battery and not was and st.mode == "explore" then
    M.note_decision(st, "battery")
  end
end

--- One control step: percepts in, actions out.
function M.step(st, p)
  local cfg = st.cfg
  -- sensing (report's doCommon, listing 6.2)
  scanner.update(st.long, p.long, p.yaw, p.tick)
  scanner.update(st.short, p.short, p.yaw, p.tick)
  scanner.update(st.expl, p.short, p.yaw, p.tick)

  local dist_nest = geometry.distance(p.x, p.y, cfg.nest_x, cfg.nest_y)
  local see, inside = ground.read(p.ground)
  local place = ground.classify(see, dist_nest, cfg.nest_radius, cfg.NEST_MARGIN, cfg.SOURCE_MARGIN)
  track_battery(st, p, place, dist_nest)

  local found = detect_source(st, p, place, inside)
  local got = listen(st, p.messages)

  local message = nil
  local k = comm.index_to_broadcast(p.tick, #st.sources)
  if k then message = comm.encode(st.sources[k].x, st.sources[k].y) end

  -- speed: slower random speed after a hit (annex 4.B)
  local prox, prox_angle = motion.strongest(p.proximity)
  local near = scanner.closest(st.short, p.yaw, pi / 2)
  local hit = prox > 0 or near < cfg.HIT_DISTANCE
  local speed = motion.update_speed(st.speed, hit, p.tick, cfg.BASE_SPEED, cfg.MIN_SPEED_COEFF,
                                    cfg.RANDOM_SPEED_TIME, st.random.uniform)

  -- decisions and movement
  local left, right
  if st.mode == "explore" then
    left, right = explore(st, p, found, got, speed)
  else
    left, right = mine(st, p, place, speed)
  end
  -- emergency avoidance overrides the wheels, never the decisions (4.4)
  if prox > 0 then
    left, right = motion.avoidance(prox_angle, prox, speed, cfg.EMER_DIR_DEP, cfg.EMER_PROX_DEP)
  end

  st.battery_prev = p.battery
  return { left = left, right = right, color = color_of(st), message = message }
end

return M
