local dir = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
package.path = dir .. "/?.lua;" .. dir .. "/../../controllers/?.lua;" .. package.path
local t = require "testlib"
local geometry = require "foraging.geometry"

t.test("angles wrap into [-pi, pi)", function()
  t.near(geometry.wrap(3 * math.pi / 2), -math.pi / 2)
  t.near(geometry.wrap(-3 * math.pi / 2), math.pi / 2)
  t.near(geometry.wrap(0.5), 0.5)
  t.near(geometry.wrap(7 * 2 * math.pi + 0.25), 0.25, 1e-9)
end)

t.test("relative angle of a goal", function()
  t.near(geometry.relative_angle(0, 0, 0, 0, 10), math.pi / 2, 1e-12, "left")
  t.near(geometry.relative_angle(0, 0, math.pi / 2, 10, 0), -math.pi / 2, 1e-12, "right")
  t.near(geometry.relative_angle(0, 0, 3, -10, 0.01), math.pi - 3 - 0.001, 1e-4)
end)

t.test("yaw from the three orientation forms", function()
  local yaw = 2.5
  local euler = { toeulerangles = function() return yaw, 0, 0 end }
  t.near(geometry.yaw_of(euler), yaw)
  -- unwrapped heading -2.5 + 2 pi: angle-axis gives angle 2 pi - ... with axis +z
  local a = -2.5 + 2 * math.pi
  local aa = { toangleaxis = function() return a, { z = 1 } end }
  t.near(geometry.yaw_of(aa), -2.5, 1e-12)
  local neg = { toangleaxis = function() return 1.0, { z = -1 } end }
  t.near(geometry.yaw_of(neg), -1.0)
  t.near(geometry.yaw_of({ angle = 1.0, axis = { z = -1 } }), -1.0)
  t.eq(geometry.yaw_of(nil), 0)
end)

t.test("direction and distance", function()
  t.near(geometry.direction(1, 1, 1, 5), math.pi / 2)
  t.near(geometry.distance(0, 0, 3, 4), 5)
end)

t.done()
