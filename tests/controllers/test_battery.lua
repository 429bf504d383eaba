local dir = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
package.path = dir .. "/?.lua;" .. dir .. "/../../controllers/?.lua;" .. package.path
local t = require "testlib"
local battery = require "foraging.battery"

t.test("needed battery: mu * batt_per_step * distance / speed", function()
  t.near(battery.needed(25, 0.2, 300, 30), 50)
  t.near(battery.needed(10, 0.2, 0, 30), 0)
end)

t.test("go home when the estimated leftover falls below IDEAL_NEST_BATT", function()
  -- needed = 50: leftover 100 - 50 = 50 >= 20 -> stay; 69 - 50 = 19 < 20 -> home
  t.ok(not battery.must_go_home(100, 25, 0.2, 300, 30, 20))
  t.ok(not battery.must_go_home(70, 25, 0.2, 300, 30, 20))
  t.ok(battery.must_go_home(69, 25, 0.2, 300, 30, 20))
  t.ok(battery.must_go_home(19, 25, 0.2, 0, 30, 20), "even at the nest")
end)

t.test("safety coefficient: surplus lowers mu by 0.07 per unit", function()
  t.near(battery.update_safety(25, 40, 20, 0.07, 0.1), 25 - 20 * 0.07)
end)

t.test("safety coefficient: deficit raises mu by 0.1 per unit", function()
  t.near(battery.update_safety(25, 5, 20, 0.07, 0.1), 25 + 15 * 0.1)
  t.near(battery.update_safety(25, 20, 20, 0.07, 0.1), 25, 1e-12, "on target: unchanged")
end)

t.test("safety coefficient never drops below the floor", function()
  t.near(battery.update_safety(2, 100, 20, 0.07, 0.1, 1), 1)
  t.ok(battery.update_safety(2, 100, 20, 0.07, 0.1) < 0, "without floor the report's law goes negative")
end)

t.test("mu converges: repeated returns with a surplus bring it down, deficits up", function()
  local mu = 25
  for _ = 1, 10 do mu = battery.update_safety(mu, 35, 20, 0.07, 0.1, 1) end
  t.near(mu, 25 - 10 * 15 * 0.07)
  for _ = 1, 10 do mu = battery.update_safety(mu, 10, 20, 0.07, 0.1, 1) end
  t.near(mu, 25 - 10 * 15 * 0.07 + 10 * 10 * 0.1)
end)

t.done()
