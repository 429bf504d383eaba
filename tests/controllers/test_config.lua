local dir = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
package.path = dir .. "/?.lua;" .. dir .. "/../../controllers/?.lua;" .. package.path
local t = require "testlib"
local config = require "foraging.config"

t.test("defaults are the report's listing 7.1", function()
  local c = config.load({ script = "foraging.lua" })
  local expected = {
    BASE_SPEED = 30, BATT_BY_STEP = 0.2, SCANNER_RPM = 75, DIR_NUMBER = 15, EXPL_DIR_NUMBER = 20,
    EXPL_CONV = 3, CONVERGENCE = 1, OBSTACLE_PROXIMITY_DEPENDANCE = 0.25,
    OBSTACLE_DIRECTION_DEPENDANCE = 0.25, EMER_DIR_DEP = 1, EMER_PROX_DEP = 1,
    MIN_SPEED_COEFF = 0.6, RANDOM_SPEED_TIME = 30, ORGN_SRC_DST = 80,
    MINE_PROB_WHEN_SRC_RECVD = 0.2, INIT_BATT_SEC = 25, IDEAL_NEST_BATT = 20, EPSILONGREED = 0.1,
  }
  for k, v in pairs(expected) do t.eq(c[k], v, k) end
  t.eq(c.nest_x, 0); t.eq(c.nest_y, 0); t.eq(c.nest_radius, 50)
  t.eq(#c.known_sources, 0)
end)

t.test("params are strings and override the defaults", function()
  local c = config.load({ EPSILONGREED = "0.3", BASE_SPEED = "20", NEST_X = "1.5", NEST_RADIUS = "0.4" })
  t.eq(c.EPSILONGREED, 0.3); t.eq(c.BASE_SPEED, 20)
  t.eq(c.nest_x, 150); t.eq(c.nest_radius, 40)
  t.raises(function() config.load({ BASE_SPEED = "fast" }) end, "BASE_SPEED")
end)

t.test("known_sources in metres become centimetres", function()
  local c = config.load({ known_sources = "-2.5,0;4.0,3.5; 4.2 , -4.2 " })
  t.eq(#c.known_sources, 3)
  t.near(c.known_sources[1][1], -250); t.near(c.known_sources[1][2], 0)
  t.near(c.known_sources[3][1], 420); t.near(c.known_sources[3][2], -420)
  t.eq(#config.parse_sources(""), 0)
  t.raises(function() config.parse_sources("1;2") end, "known_sources")
end)

t.done()
