-- Constants of the foraging behaviour (report, listing 7.1) and their parsing from robot.params.
--
-- Every constant can be overridden by an attribute of the controller's <params> node (ARGoS hands
-- them to Lua as strings). Units follow the report: centimetres, cm/s, battery units (0..100),
-- simulation steps. NEST_X / NEST_Y / NEST_RADIUS and known_sources are in metres, like the XML.
local M = {}

M.DEFAULTS = {
  -- specs received
  BASE_SPEED = 30,            -- cm/s
  BATT_BY_STEP = 0.2,         -- battery units lost per step
  -- low level
  SCANNER_RPM = 75,
  DIR_NUMBER = 15,            -- directions the distance-scanner readings are grouped into
  EXPL_DIR_NUMBER = 20,       -- same, while exploring (gas-like walk)
  EXPL_CONV = 3,              -- kappa of the sharp turns of the gas-like walk
  -- movement
  CONVERGENCE = 1,            -- kappa of the convergence law (4.2)
  OBSTACLE_PROXIMITY_DEPENDANCE = 0.25,  -- beta of the intermediate avoidance (4.5)
  OBSTACLE_DIRECTION_DEPENDANCE = 0.25,  -- alpha of the intermediate avoidance (4.5)
  EMER_DIR_DEP = 1,           -- alpha of the emergency avoidance (4.4)
  EMER_PROX_DEP = 1,          -- beta of the emergency avoidance (4.4)
  MIN_SPEED_COEFF = 0.6,      -- after a hit: speed drawn in [MIN_SPEED_COEFF, 1] * BASE_SPEED
  RANDOM_SPEED_TIME = 30,     -- steps the random speed is kept
  -- decision making
  ORGN_SRC_DST = 80,          -- cm: closer sources are the same source
  MINE_PROB_WHEN_SRC_RECVD = 0.2,
  INIT_BATT_SEC = 25,         -- initial battery safety coefficient mu
  IDEAL_NEST_BATT = 20,       -- battery a robot should have left when back at the nest
  EPSILONGREED = 0.1,

  -- Not in listing 7.1: values the report's code hard-wires, named so they can be swept too.
  HIT_DISTANCE = 30,          -- cm: short-range obstacle closer than this = a "hit" (listings 4.11, 6.7)
  FREE_DISTANCE = 151,        -- cm: value of a direction where the scanner sees nothing (listing 4.3)
  AVOID_CONE = math.pi / 3,   -- rad: intermediate avoidance reacts to obstacles within this of the front
  TURN_TOLERANCE = 0.2,       -- rad: a gas-like rebound turn is over within this angle (listing 6.7)
  INIT_SCORE = 1,             -- optimistic quality score of a new source (listing 6.3)
  BATT_GAIN_DOWN = 0.07,      -- mu decrease per unit of surplus at the nest (listing 6.13)
  BATT_GAIN_UP = 0.1,         -- mu increase per unit of deficit at the nest (listing 6.13)
  NEST_MARGIN = 20,           -- cm: black within NEST_RADIUS + this of the nest centre is the nest (70)
  SOURCE_MARGIN = 40,         -- cm: black beyond NEST_RADIUS + this is a source (90)
  MIN_SAFETY = 10,            -- mu never goes below this (see battery.lua): at 10 steps per
                              -- second, mu = 10 makes needed() a straight-line return's cost

  -- arena
  NEST_X = 0, NEST_Y = 0, NEST_RADIUS = 0.5,   -- metres
}

--- Parses "x,y;x,y;..." (metres) into an array of {x, y} in centimetres. Blank or nil -> {}.
function M.parse_sources(text)
  local out = {}
  if text == nil then return out end
  for item in string.gmatch(text, "[^;]+") do
    local xs, ys = item:match("^%s*([^,%s]+)%s*,%s*([^,%s]+)%s*$")
    local x, y = tonumber(xs), tonumber(ys)
    if x == nil or y == nil then
      error("known_sources: cannot read '" .. item .. "' (expected x,y in metres)")
    end
    out[#out + 1] = { x * 100, y * 100 }
  end
  return out
end

--- Builds the configuration from a params table of strings (robot.params); missing keys take the
--- defaults. Adds nest_x, nest_y, nest_radius in centimetres and known_sources (cm).
function M.load(params)
  params = params or {}
  local cfg = {}
  for k, v in pairs(M.DEFAULTS) do
    local given = params[k]
    if given ~= nil then
      local n = tonumber(given)
      if n == nil then error("param " .. k .. ": not a number: '" .. tostring(given) .. "'") end
      cfg[k] = n
    else
      cfg[k] = v
    end
  end
  cfg.nest_x = cfg.NEST_X * 100
  cfg.nest_y = cfg.NEST_Y * 100
  cfg.nest_radius = cfg.NEST_RADIUS * 100
  cfg.known_sources = M.parse_sources(params.known_sources)
  return cfg
end

return M
