local dir = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
package.path = dir .. "/?.lua;" .. dir .. "/../../controllers/?.lua;" .. package.path
local t = require "testlib"
local scanner = require "foraging.scanner"

local pi = math.pi

t.test("sectors cover the turn; centre of an odd count is straight ahead", function()
  local n = 15
  t.near(scanner.centre(8, n), 0, 1e-12)
  t.near(scanner.centre(1, n), -pi + pi / n)
  t.near(scanner.centre(n, n), pi - pi / n)
  for k = 1, n do
    t.eq(scanner.sector(scanner.centre(k, n), n), k, "centre of " .. k)
  end
  t.eq(scanner.sector(pi, n), 1, "pi wraps to -pi")
  t.eq(scanner.sector(-pi, n), 1)
  t.eq(scanner.sector(pi - 1e-9, n), n)
end)

t.test("-2 means nothing seen, -1 means too close", function()
  t.eq(scanner.reading_value(-2, 151), 151)
  t.eq(scanner.reading_value(-1, 151), 0)
  t.eq(scanner.reading_value(42.5, 151), 42.5)
  t.eq(scanner.reading_value(500, 151), 151)
end)

t.test("the least optimistic reading of a step is kept per sector", function()
  local tb = scanner.new(4, 151)
  scanner.update(tb, {
    { angle = 0.1, distance = 80 }, { angle = 0.2, distance = 30 }, { angle = 0.3, distance = -2 },
  }, 0, 1)
  local k = scanner.sector(0.1, 4)
  t.eq(tb.value[k], 30)
  t.eq(tb.value[scanner.sector(-2, 4)], 151, "untouched sector stays free")
  scanner.update(tb, { { angle = 0.15, distance = -1 } }, 0, 2)
  t.eq(tb.value[k], 0, "too close counts as 0")
end)

t.test("a new step replaces a sector's value, a sector without readings keeps it", function()
  local tb = scanner.new(4, 151)
  scanner.update(tb, { { angle = 0.1, distance = 30 }, { angle = 2.0, distance = 50 } }, 0, 1)
  scanner.update(tb, { { angle = 0.1, distance = 90 }, { angle = 0.2, distance = -2 } }, 0, 2)
  t.eq(tb.value[scanner.sector(0.1, 4)], 90)
  t.eq(tb.value[scanner.sector(2.0, 4)], 50)
end)

t.test("offset moves readings into another frame", function()
  local tb = scanner.new(8, 151)
  scanner.update(tb, { { angle = 0, distance = 20 } }, pi / 2, 1)
  t.eq(tb.value[scanner.sector(pi / 2, 8)], 20)
  local d, a = scanner.closest(tb, pi / 2)
  t.eq(d, 20)
  t.near(a, 0, 1e-12, "back in the robot frame")
end)

t.test("closest obstacle, restricted to the front half", function()
  local tb = scanner.new(15, 151)
  scanner.update(tb, { { angle = pi - 0.1, distance = 5 }, { angle = 0.5, distance = 20 } }, 0, 1)
  local d, a = scanner.closest(tb)
  t.eq(d, 5); t.ok(a > 2.5)
  d, a = scanner.closest(tb, 0, pi / 2)
  t.eq(d, 20); t.near(a, 0.5, 1e-12, "the reading's own angle")
  local empty = scanner.new(15, 151)
  d = scanner.closest(empty)
  t.eq(d, 151)
end)

t.test("closest keeps the side of an obstacle dead ahead", function()
  local tb = scanner.new(15, 151)
  scanner.update(tb, { { angle = -0.05, distance = 12 } }, 0, 1)
  local _, a = scanner.closest(tb)
  t.near(a, -0.05, 1e-12)
  scanner.update(tb, { { angle = 0.05, distance = 30 }, { angle = 0.1, distance = 8 } }, 0, 2)
  local d
  d, a = scanner.closest(tb)
  t.eq(d, 8); t.near(a, 0.1, 1e-12, "angle of the retained (smallest) reading")
end)

t.test("greedy: free goal direction is taken as is", function()
  local tb = scanner.new(15, 151)
  local d, v = scanner.best_direction(tb, 0.3)
  t.near(d, 0.3); t.eq(v, 151)
end)

t.test("greedy: blocked goal -> nearest free direction", function()
  local n = 15
  local tb = scanner.new(n, 151)
  local goal = 0.05
  local g = scanner.sector(goal, n)
  tb.value[g] = 40
  tb.value[g + 1] = 60
  local d = scanner.best_direction(tb, goal)
  t.near(d, scanner.centre(g - 1, n), 1e-12, "the free neighbour on the other side")
  tb.value[g - 1] = 100
  d = scanner.best_direction(tb, goal)
  t.near(d, scanner.centre(g + 2, n), 1e-12)
end)

t.test("greedy: nothing free -> farthest obstacle", function()
  local n = 6
  local tb = scanner.new(n, 151)
  for k = 1, n do tb.value[k] = 10 * k end
  local d, v = scanner.best_direction(tb, scanner.centre(1, n))
  t.eq(v, 60); t.near(d, scanner.centre(6, n))
end)

t.test("greedy: obstacles beyond the goal do not matter", function()
  local n = 15
  local tb = scanner.new(n, 151)
  tb.value[scanner.sector(0, n)] = 120
  local d = scanner.best_direction(tb, 0, 80)
  t.near(d, 0, 1e-12, "goal 80 cm away, obstacle at 120 cm")
  d = scanner.best_direction(tb, 0, 140)
  t.ok(math.abs(d) > 0.1, "goal beyond the obstacle")
end)

t.test("greedy: angular distance wraps around pi", function()
  local n = 15
  local tb = scanner.new(n, 151)
  for k = 1, n do tb.value[k] = 50 end
  tb.value[1] = 151        -- just past -pi
  tb.value[8] = 151        -- straight ahead
  local d = scanner.best_direction(tb, pi - 0.2)
  t.near(d, scanner.centre(1, n), 1e-12, "closest through the wrap")
end)

t.done()
