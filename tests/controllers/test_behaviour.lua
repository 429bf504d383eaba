local dir = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
package.path = dir .. "/?.lua;" .. dir .. "/../../controllers/?.lua;" .. package.path
local t = require "testlib"
local behaviour = require "foraging.behaviour"
local config = require "foraging.config"
local comm = require "foraging.comm"
local motion = require "foraging.motion"

local pi = math.pi

local function percepts(over)
  local p = { tick = 1, x = 0, y = 0, yaw = 0, battery = 100, ground = {}, proximity = {},
              short = {}, long = {}, messages = {} }
  for i = 1, 8 do p.ground[i] = { value = 1 } end
  for i = 1, 24 do p.proximity[i] = { value = 0, angle = motion.proximity_angle(i) } end
  for k, v in pairs(over or {}) do p[k] = v end
  return p
end

local function black(p)
  for i = 1, 8 do p.ground[i].value = 0 end
  return p
end

local function fresh(params, seed)
  return behaviour.new(config.load(params or {}), t.rng(seed or 1))
end

t.test("a new robot explores: green, straight at BASE_SPEED, silent", function()
  local st = fresh()
  t.eq(st.mode, "explore")
  local a = behaviour.step(st, percepts())
  t.eq(a.color, "green")
  t.near(a.left, 30); t.near(a.right, 30)
  t.eq(a.message, nil)
end)

t.test("rebound off an obstacle ahead, then straight again", function()
  t.near(behaviour.rebound(0), -pi, 1e-12, "head-on: turn back")
  t.near(behaviour.rebound(pi / 2), 0, 1e-12, "grazing on the side: keep going")
  t.near(behaviour.rebound(pi / 6), -2 * pi / 3, 1e-12)
  t.near(behaviour.rebound(-pi / 6), 2 * pi / 3, 1e-12)
  local st = fresh()
  local a = behaviour.step(st, percepts({ short = { { angle = 0.3, distance = 10 } } }))
  t.ok(st.turn_to ~= nil, "turning")
  t.ok(a.left > a.right, "obstacle front-left: turn right")
  local target = st.turn_to
  a = behaviour.step(st, percepts({ tick = 2, yaw = target + 0.05 }))
  t.eq(st.turn_to, nil, "turn over")
  t.near(a.left, a.right, 1e-9)
end)

t.test("finding a source: recorded, mining, going home first, then broadcast", function()
  local st = fresh()
  local a = behaviour.step(st, black(percepts({ x = 300, y = -120 })))
  t.eq(#st.sources, 1)
  t.eq(st.sources[1].x, 300); t.eq(st.sources[1].y, -120)
  t.eq(st.sources[1].score, 1, "optimistic initial score")
  t.eq(st.mode, "mine"); t.ok(st.going_home)
  t.eq(a.color, "orange")
  t.ok(a.message ~= nil)
  local x, y = comm.decode(a.message)
  t.eq(x, 300); t.eq(y, -120)
end)

t.test("touching a source with some sensors only does not record it", function()
  local st = fresh()
  local p = percepts({ x = 300, y = 0 })
  p.ground[1].value = 0
  behaviour.step(st, p)
  t.eq(#st.sources, 0)
end)

t.test("the black nest is not a source", function()
  local st = fresh()
  behaviour.step(st, black(percepts({ x = 30, y = 10 })))
  t.eq(#st.sources, 0)
  t.eq(st.mode, "explore")
end)

t.test("a received source is learnt; mining starts with MINE_PROB_WHEN_SRC_RECVD", function()
  local st = fresh({ MINE_PROB_WHEN_SRC_RECVD = "0" })
  behaviour.step(st, percepts({ messages = { comm.encode(-250, 10) } }))
  t.eq(#st.sources, 1); t.eq(st.mode, "explore")
  st = fresh({ MINE_PROB_WHEN_SRC_RECVD = "1" })
  local a = behaviour.step(st, percepts({ messages = { comm.encode(-250, 10), { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 } } }))
  t.eq(#st.sources, 1); t.eq(st.mode, "mine"); t.ok(st.going_home, "refill at the nest first")
  t.eq(a.color, "orange")
  -- the same source again (within ORGN_SRC_DST) is not new
  behaviour.step(st, percepts({ tick = 2, messages = { comm.encode(-200, 40) } }))
  t.eq(#st.sources, 1)
end)

t.test("mining frequencies: MINE_PROB_WHEN_SRC_RECVD = 0.2", function()
  local started = 0
  for seed = 1, 2000 do
    local st = fresh({}, seed)
    behaviour.step(st, percepts({ messages = { comm.encode(-250, 10) } }))
    if st.mode == "mine" then started = started + 1 end
  end
  t.near(started / 2000, 0.2, 0.04)
end)

t.test("a mining trip: nest -> choose source (yellow) -> source: trip scored -> home", function()
  local st = fresh({ known_sources = "-2.5,0" })
  t.eq(st.mode, "mine"); t.eq(st.target, 1); t.eq(st.going_home, false)
  local a = behaviour.step(st, black(percepts({ tick = 1, x = 0, y = 0, battery = 100 })))
  t.eq(a.color, "yellow")
  -- heading for (-250, 0) from the origin facing +x: goal behind, turns
  a = behaviour.step(st, percepts({ tick = 2, x = 60, y = 0, battery = 99 }))
  t.ok(math.abs(a.left - a.right) > 1, "turning towards the source")
  a = behaviour.step(st, black(percepts({ tick = 3, x = -210, y = 0, battery = 84 })))
  t.eq(st.sources[1].trips, 1)
  t.near(st.sources[1].spent, 100 - 84)
  t.near(st.sources[1].score, 1 / 16)
  t.ok(st.going_home); t.eq(a.color, "orange")
  -- touching it again on the way home counts nothing
  behaviour.step(st, black(percepts({ tick = 4, x = -205, y = 0, battery = 83 })))
  t.eq(st.sources[1].trips, 1)
  -- home: a new target is chosen
  a = behaviour.step(st, black(percepts({ tick = 5, x = 20, y = 0, battery = 100 })))
  t.eq(st.going_home, false); t.eq(st.target, 1); t.eq(a.color, "yellow")
end)

t.test("greedy convergence towards a free goal on the left", function()
  local st = fresh({ known_sources = "0,3" })
  local a = behaviour.step(st, percepts({ x = 0, y = 0, yaw = 0 }))
  t.ok(a.right > a.left, "goal on the left: right wheel faster")
  t.near((a.left + a.right) / 2, 30, 1e-9)
end)

t.test("intermediate avoidance of a short-range obstacle in front", function()
  local st = fresh({ known_sources = "3,0" })
  local a = behaviour.step(st, percepts({ x = 0, y = 0, yaw = 0,
                                          short = { { angle = -0.1, distance = 12 } } }))
  t.ok(a.right > a.left, "obstacle front-right while the goal is ahead: turn left")
end)

t.test("battery: far from home with little charge -> red, back home, trip aborted", function()
  local st = fresh({ known_sources = "4.0,3.5" })
  behaviour.step(st, black(percepts({ tick = 1, battery = 100 })))
  -- mu 25: needed = 25 * 0.2 * 400 / 30 = 66.7; 80 - 66.7 = 13.3 < 20
  local a = behaviour.step(st, percepts({ tick = 2, x = 400, y = 0, battery = 80 }))
  t.ok(st.back_for_battery); t.eq(a.color, "red"); t.ok(st.going_home)
  t.near(st.sources[1].spent, 100, 1e-9, "the abandoned trip is charged a whole battery")
  t.eq(st.sources[1].trips, 0)
  t.eq(st.sources[1].score, 0)
  t.eq(st.why, "battery")
  -- back at the nest with 30 units: surplus 10 -> mu - 0.7
  behaviour.step(st, percepts({ tick = 3, x = 60, y = 0, battery = 31 }))
  behaviour.step(st, black(percepts({ tick = 4, x = 40, y = 0, battery = 30 })))
  t.near(st.mu, 25 - 10 * 0.07)
  t.ok(not st.back_for_battery)
end)

t.test("battery: mu is judged at every return, a miner's loaded ones too, never below MIN_SAFETY", function()
  local st = fresh({ known_sources = "-2.5,0" })
  behaviour.step(st, black(percepts({ tick = 1, battery = 100 })))
  t.eq(st.mu, 25, "leaving the nest is no return")
  behaviour.step(st, percepts({ tick = 2, x = -120, y = 0, battery = 95 }))
  behaviour.step(st, black(percepts({ tick = 3, x = -210, y = 0, battery = 88 })))
  t.eq(st.going_home, true); t.eq(st.why, "trip")
  behaviour.step(st, percepts({ tick = 4, x = -120, y = 0, battery = 82 }))
  t.ok(not st.back_for_battery, "a plain trip home")
  behaviour.step(st, black(percepts({ tick = 5, x = 40, y = 0, battery = 76 })))
  t.near(st.mu, 25 - (76 - 20) * 0.07, 1e-9, "the surplus of a loaded return lowers mu")
  t.eq(st.why, "greedy")
  -- wandering on the nest's edge is no new return
  behaviour.step(st, percepts({ tick = 6, x = 75, y = 0, battery = 100 }))
  behaviour.step(st, black(percepts({ tick = 7, x = 45, y = 0, battery = 100 })))
  t.near(st.mu, 25 - 56 * 0.07, 1e-9)
  for k = 1, 6 do
    behaviour.step(st, percepts({ tick = 6 + 2 * k, x = -150, y = 0, battery = 90 }))
    behaviour.step(st, black(percepts({ tick = 7 + 2 * k, x = 40, y = 0, battery = 85 })))
  end
  t.eq(st.mu, 10, "floored at MIN_SAFETY")
end)

t.test("decisions are counted with their reasons", function()
  local st = fresh({ known_sources = "-2.5,0;4.0,3.5", EPSILONGREED = "0" })
  t.eq(st.decisions, 1, "the first pick"); t.eq(st.why, "greedy")
  local ex = fresh({ MINE_PROB_WHEN_SRC_RECVD = "1" })
  behaviour.step(ex, percepts({ messages = { comm.encode(-250, 10) } }))
  t.eq(ex.decisions, 1); t.eq(ex.why, "message")
  local finder = fresh()
  behaviour.step(finder, black(percepts({ x = 300, y = -120 })))
  t.eq(finder.why, "found")
  local lost = fresh()
  behaviour.step(lost, percepts({ tick = 1, x = 450, y = 0, battery = 70 }))
  t.eq(lost.why, "battery", "an explorer sent home")
  behaviour.step(lost, percepts({ tick = 2, x = 440, y = 0, battery = 69 }))
  t.eq(lost.decisions, 1, "noted once")
  local eps = fresh({ known_sources = "-2.5,0;4.0,3.5", EPSILONGREED = "1" })
  t.eq(eps.why, "epsilon")
end)

t.test("battery: a refill seen on arrival does not hide a late return", function()
  local st = fresh()
  behaviour.step(st, percepts({ tick = 1, x = 450, y = 0, battery = 70 }))
  t.ok(st.back_for_battery)
  behaviour.step(st, percepts({ tick = 2, x = 70, y = 0, battery = 15 }))
  behaviour.step(st, black(percepts({ tick = 3, x = 50, y = 0, battery = 100 })))
  t.near(st.mu, 25 + 5 * 0.1)
end)

t.test("battery: an explorer keeps exploring after refilling", function()
  local st = fresh()
  behaviour.step(st, percepts({ tick = 1, x = 450, y = 0, battery = 70 }))
  t.eq(st.mode, "explore"); t.ok(st.back_for_battery)
  behaviour.step(st, black(percepts({ tick = 2, x = 40, y = 0, battery = 100 })))
  local a = behaviour.step(st, percepts({ tick = 3, x = 20, y = 0, battery = 100 }))
  t.eq(a.color, "green")
end)

t.test("emergency avoidance overrides the wheels", function()
  local st = fresh()
  local p = percepts()
  p.proximity[3].value = 0.5
  local a = behaviour.step(st, p)
  local l, r = motion.avoidance(motion.proximity_angle(3), 0.5, st.speed.speed, 1, 1)
  t.near(a.left, l); t.near(a.right, r)
  t.ok(a.left > a.right, "obstacle on the left: turn right")
end)

t.test("a hit slows the robot to a random speed", function()
  local st = fresh()
  local p = percepts()
  p.proximity[12].value = 0.2
  behaviour.step(st, p)
  t.ok(st.speed.speed >= 18 and st.speed.speed <= 30)
  t.eq(st.speed.last_hit, 1)
end)

t.test("known sources are broadcast in turn", function()
  local st = fresh({ known_sources = "-2.5,0;4.0,3.5" })
  local seen = {}
  for tick = 1, 4 do
    local a = behaviour.step(st, percepts({ tick = tick, x = 0, y = 200 }))
    local x = comm.decode(a.message)
    seen[#seen + 1] = x
  end
  t.eq(table.concat(seen, ","), "400,-250,400,-250")
end)

t.done()
