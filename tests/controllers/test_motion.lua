local dir = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
package.path = dir .. "/?.lua;" .. dir .. "/../../controllers/?.lua;" .. package.path
local t = require "testlib"
local motion = require "foraging.motion"

local pi = math.pi

t.test("convergence: theta = 0 gives both wheels SPEED", function()
  for _, kappa in ipairs({ 0.5, 1, 3 }) do
    local l, r = motion.convergence(0, 30, kappa)
    t.near(l, 30); t.near(r, 30)
  end
end)

t.test("convergence: goal on the left makes the right wheel faster", function()
  for _, theta in ipairs({ 0.01, 0.3, pi / 2, 3, pi }) do
    local l, r = motion.convergence(theta, 30, 1)
    t.ok(r > l, "theta=" .. theta)
    t.near((l + r) / 2, 30, 1e-9, "mean speed stays SPEED")
  end
end)

t.test("convergence: goal on the right makes the left wheel faster", function()
  for _, theta in ipairs({ -0.01, -0.3, -pi / 2, -3 }) do
    local l, r = motion.convergence(theta, 30, 1)
    t.ok(l > r, "theta=" .. theta)
  end
end)

t.test("convergence: symmetric", function()
  for _, kappa in ipairs({ 1, 3 }) do
    for theta = 0.05, pi, 0.1 do
      local l1, r1 = motion.convergence(theta, 25, kappa)
      local l2, r2 = motion.convergence(-theta, 25, kappa)
      t.near(l1, r2); t.near(r1, l2)
    end
  end
end)

t.test("convergence: the report's formula and kappa's effect", function()
  local theta = pi / 3
  local l, r = motion.convergence(theta, 30, 2)
  t.near(l, ((pi - theta) / pi) ^ 2 * 30)
  t.near(r, 60 - l)
  local l1 = motion.convergence(theta, 30, 1)
  local l3 = motion.convergence(theta, 30, 3)
  t.ok(l3 < l1, "larger kappa turns harder")
  local lp, rp = motion.convergence(pi, 30, 1)
  t.near(lp, 0); t.near(rp, 60)
end)

t.test("side index matches the proximity ring numbering", function()
  for i = 1, 24 do
    local s = motion.side_index(motion.proximity_angle(i))
    local expected = i <= 12 and i or 25 - i
    t.near(s, expected, 1e-9, "sensor " .. i)
  end
end)

t.test("avoidance reproduces the report's formula with ring indices", function()
  local speed, alpha, beta = 30, 1, 1
  for i = 1, 24 do
    for _, prox in ipairs({ 0.05, 0.5, 0.95 }) do
      local l, r = motion.avoidance(motion.proximity_angle(i), prox, speed, alpha, beta)
      local el, er
      if i <= 12 then
        er = ((1 - prox) ^ beta * i - alpha) * speed / 11
        el = 2 * speed - er
      else
        el = ((1 - prox) ^ beta * (25 - i) - alpha) * speed / 11
        er = 2 * speed - el
      end
      t.near(l, el, 1e-9, "left " .. i); t.near(r, er, 1e-9, "right " .. i)
    end
  end
end)

t.test("avoidance turns away from the obstacle", function()
  -- obstacle front-left -> turn right (left wheel faster), and the reverse
  local l, r = motion.avoidance(0.3, 0.6, 30, 1, 1)
  t.ok(l > r, "front-left obstacle")
  l, r = motion.avoidance(-0.3, 0.6, 30, 1, 1)
  t.ok(r > l, "front-right obstacle")
end)

t.test("avoidance: closer and more frontal obstacles turn harder", function()
  local function turn(theta, prox)
    local l, r = motion.avoidance(theta, prox, 30, 0.25, 0.25)
    return math.abs(l - r)
  end
  t.ok(turn(0.2, 0.9) > turn(0.2, 0.2), "proximity")
  t.ok(turn(0.2, 0.5) > turn(2.0, 0.5), "direction")
  -- a far obstacle right behind: nearly straight
  local l, r = motion.avoidance(pi - 0.01, 0, 30, 1, 1)
  t.near(l, 30, 1.5); t.near(r, 30, 1.5)
end)

t.test("avoidance is symmetric", function()
  for theta = 0.1, 3.1, 0.2 do
    local l1, r1 = motion.avoidance(theta, 0.4, 30, 0.25, 0.25)
    local l2, r2 = motion.avoidance(-theta, 0.4, 30, 0.25, 0.25)
    t.near(l1, r2); t.near(r1, l2)
  end
end)

t.test("strongest proximity reading, ties to the most frontal", function()
  local ring = {}
  for i = 1, 24 do ring[i] = { value = 0, angle = motion.proximity_angle(i) } end
  local v, a = motion.strongest(ring)
  t.eq(v, 0)
  ring[5].value = 0.3; ring[20].value = 0.7
  v, a = motion.strongest(ring)
  t.eq(v, 0.7); t.near(a, motion.proximity_angle(20))
  ring[2].value = 0.7
  v, a = motion.strongest(ring)
  t.near(a, motion.proximity_angle(2), 1e-12, "sensor 2 is more frontal than 20")
end)

t.test("closeness of a short-range obstacle", function()
  t.near(motion.closeness(0, 30), 1)
  t.near(motion.closeness(15, 30), 0.5)
  t.near(motion.closeness(30, 30), 0)
  t.near(motion.closeness(151, 30), 0)
end)

t.test("random speed after a hit (annex 4.B)", function()
  local draws = 0
  local function uniform(a, b)
    draws = draws + 1
    t.eq(a, 0.6); t.eq(b, 1)
    return 0.75
  end
  local st = motion.new_speed_state(30)
  t.eq(motion.update_speed(st, false, 1, 30, 0.6, 30, uniform), 30)
  t.near(motion.update_speed(st, true, 10, 30, 0.6, 30, uniform), 22.5)
  t.eq(draws, 1)
  -- kept during RANDOM_SPEED_TIME steps, a new hit extends it without a new draw
  t.near(motion.update_speed(st, false, 30, 30, 0.6, 30, uniform), 22.5)
  t.near(motion.update_speed(st, true, 35, 30, 0.6, 30, uniform), 22.5)
  t.eq(draws, 1)
  t.near(motion.update_speed(st, false, 65, 30, 0.6, 30, uniform), 22.5)
  t.eq(motion.update_speed(st, false, 66, 30, 0.6, 30, uniform), 30)
  -- a hit after expiry draws again
  motion.update_speed(st, true, 200, 30, 0.6, 30, uniform)
  t.eq(draws, 2)
end)

t.test("random speed stays in [MIN_SPEED_COEFF, 1] * BASE_SPEED", function()
  local rng = t.rng(3)
  local st = motion.new_speed_state(30)
  for k = 1, 500 do
    local s = motion.update_speed(st, true, k * 100, 30, 0.6, 30, rng.uniform)
    t.ok(s >= 18 and s <= 30)
  end
end)

t.done()
