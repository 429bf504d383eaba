// The template texts of `essaim new`. @NAME@, @ESSAIM@ and the like are filled in by
// ProjectFiles; everything else is written as is.
#include "app/project_templates.h"

#include <string>

namespace essaim {

namespace {
const char* kEmptyController = R"(-- @NAME@: the controller of every foot-bot (essaim new, template "empty").
-- essaim calls init() once, step() every tick, reset() on a reset and destroy() at the end.
-- robot.* holds the devices the .argos file declares (essaim devices lists them all).

local speed  -- cm/s, from <params speed="..."> (every parameter arrives as a string)

function init()
  speed = tonumber(robot.params.speed) or 10
end

-- Straight ahead; turn on the spot while something is close in front.
function step()
  local front = 0
  for i = 1, 24 do
    local reading = robot.proximity[i]
    if math.abs(reading.angle) < math.pi / 3 then front = math.max(front, reading.value) end
  end
  if front > 0.2 then
    robot.wheels.set_velocity(speed, -speed)
  else
    robot.wheels.set_velocity(speed, speed)
  end
end

function reset() init() end

function destroy() end
)";

const char* kEmptyLoop = R"(-- @NAME@: loop functions (docs/loop-functions.md). One metric: how far the robots got from
-- where they started, written into metrics.json by post_experiment().

local start = {}  -- robot id -> {x, y}

function init()
  for _, r in ipairs(experiment.robots) do
    local x, y = r:position()
    start[r.id] = {x, y}
  end
end

-- metrics.json: moved = mean distance (m) between each robot's start and end positions.
function post_experiment()
  local sum = 0
  for _, r in ipairs(experiment.robots) do
    local x, y = r:position()
    sum = sum + math.sqrt((x - start[r.id][1]) ^ 2 + (y - start[r.id][2]) ^ 2)
  end
  return {moved = sum / #experiment.robots}
end
)";

const char* kAggregationController =
    R"(-- @NAME@: aggregation (essaim new, template "aggregation"). Each robot tells the others it
-- is there (range-and-bearing), steers towards the mean bearing of the robots it hears, and
-- wanders when it hears none. init() once, step() every tick, reset(), destroy() at the end.

local speed  -- cm/s, from <params speed="...">

function init()
  speed = tonumber(robot.params.speed) or 10
  robot.range_and_bearing.set_data(1, 1)
  robot.leds.set_all_colors("green")
end

-- The largest proximity reading within 60 degrees of the front, and its angle.
local function obstacle()
  local value, angle = 0, 0
  for i = 1, 24 do
    local r = robot.proximity[i]
    if math.abs(r.angle) < math.pi / 3 and r.value > value then value, angle = r.value, r.angle end
  end
  return value, angle
end

-- The mean bearing of the robots heard (a sum of unit vectors), nil when none is heard.
local function swarm_bearing()
  local x, y = 0, 0
  for _, m in ipairs(robot.range_and_bearing) do
    x = x + math.cos(m.horizontal_bearing)
    y = y + math.sin(m.horizontal_bearing)
  end
  if #robot.range_and_bearing == 0 then return nil end
  return math.atan(y, x)
end

local function steer(angle)
  local turn = math.max(-1, math.min(1, angle / (math.pi / 2)))
  robot.wheels.set_velocity(speed * (1 - turn), speed * (1 + turn))
end

function step()
  local close, side = obstacle()
  local bearing = swarm_bearing()
  if close > 0.5 then
    robot.wheels.set_velocity(0, 0)  -- arrived: another robot (or a wall) right in front
  elseif close > 0.1 then
    steer(side > 0 and -math.pi / 2 or math.pi / 2)
  elseif bearing then
    steer(bearing)
  else
    steer(robot.random.uniform(-1, 1))
  end
end

function reset() init() end

function destroy() end
)";

const char* kAggregationLoop = R"(-- @NAME@: loop functions (docs/loop-functions.md). One metric: how much the swarm
-- gathered, the spread (mean distance to the swarm's centre) at the end over that at start.

local function spread()
  local cx, cy, n = 0, 0, #experiment.robots
  for _, r in ipairs(experiment.robots) do
    local x, y = r:position()
    cx, cy = cx + x / n, cy + y / n
  end
  local sum = 0
  for _, r in ipairs(experiment.robots) do
    local x, y = r:position()
    sum = sum + math.sqrt((x - cx) ^ 2 + (y - cy) ^ 2)
  end
  return sum / n
end

local spread_start

function init() spread_start = spread() end

-- metrics.json: shrink = spread at the end / spread at start (below 1: the swarm gathered).
function post_experiment()
  local spread_end = spread()
  return {spread_start = spread_start, spread_end = spread_end, shrink = spread_end / spread_start}
end
)";

const char* kForagingController =
    R"(-- @NAME@: foraging (essaim new, template "foraging"). Robots wander until their motor ground
-- sensor sees a grey food patch, pick up food there (LEDs red), drive home to the black nest in
-- the middle (positioning), drop it (LEDs green) and go out again. init() once, step() every
-- tick, reset(), destroy() at the end.

local speed   -- cm/s, from <params speed="...">
carrying = false  -- globals: the loop functions read them (r:lua_global)
deliveries = 0

function init()
  speed = tonumber(robot.params.speed) or 10
  carrying, deliveries = false, 0
  robot.leds.set_all_colors("green")
end

-- The floor under the robot: the mean of the four motor ground readings (0 black .. 1 white).
local function floor_level()
  local sum = 0
  for i = 1, 4 do sum = sum + robot.motor_ground[i].value end
  return sum / 4
end

-- The largest proximity reading within 60 degrees of the front, and its angle.
local function obstacle()
  local value, angle = 0, 0
  for i = 1, 24 do
    local r = robot.proximity[i]
    if math.abs(r.angle) < math.pi / 3 and r.value > value then value, angle = r.value, r.angle end
  end
  return value, angle
end

-- The nest's direction in the robot's frame (rad), from the positioning sensor.
local function nest_bearing()
  local p = robot.positioning.position
  local yaw = robot.positioning.orientation:toeulerangles()
  local a = math.atan(-p.y, -p.x) - yaw
  return math.atan(math.sin(a), math.cos(a))
end

local function steer(angle)
  local turn = math.max(-1, math.min(1, angle / (math.pi / 2)))
  robot.wheels.set_velocity(speed * (1 - turn), speed * (1 + turn))
end

function step()
  local level = floor_level()
  if not carrying and level > 0.3 and level < 0.7 then
    carrying = true
    robot.leds.set_all_colors("red")
  elseif carrying and level < 0.2 then
    carrying, deliveries = false, deliveries + 1
    robot.leds.set_all_colors("green")
  end
  local close, side = obstacle()
  if close > 0.1 then
    steer(side > 0 and -math.pi / 2 or math.pi / 2)
  elseif carrying then
    steer(nest_bearing())
  else
    steer(robot.random.uniform(-0.6, 0.6))
  end
end

function reset() init() end

function destroy() end
)";

const char* kForagingLoop =
    R"(-- @NAME@: loop functions (docs/loop-functions.md). The floor: a black nest in the middle and
-- four grey food patches; one metric: the food delivered to the nest, over the swarm.

local NEST_RADIUS = 0.4
local PATCHES = {{1.3, 1.3}, {-1.3, 1.3}, {1.3, -1.3}, {-1.3, -1.3}}
local PATCH_RADIUS = 0.35

function floor_color(x, y)
  if x * x + y * y < NEST_RADIUS ^ 2 then return 0, 0, 0 end
  for _, p in ipairs(PATCHES) do
    if (x - p[1]) ^ 2 + (y - p[2]) ^ 2 < PATCH_RADIUS ^ 2 then return 128, 128, 128 end
  end
  return 255, 255, 255
end

-- metrics.json: deliveries over the swarm, and per robot on average.
function post_experiment()
  local total = 0
  for _, r in ipairs(experiment.robots) do total = total + (r:lua_global("deliveries") or 0) end
  return {deliveries = total, deliveries_per_robot = total / #experiment.robots}
end
)";

const ProjectTemplate kTemplates[] = {
    {"empty", kEmptyController, kEmptyLoop,
     "  \"each errors == 0\",\n  \"mean moved > 0.3\",          # metres from the start, on average\n", "300",
     "every robot drives ahead and turns away from what is in front"},
    {"aggregation", kAggregationController, kAggregationLoop,
     "  \"each errors == 0\",\n"
     "  \"median shrink < 0.6\",                  # the swarm's spread at least 40% smaller\n"
     "  \"fraction(shrink < 0.8) >= 0.8\",        # and gathered in at least 8 runs of 10\n",
     "600", "the robots gather: each steers towards the robots it hears over range-and-bearing"},
    {"foraging", kForagingController, kForagingLoop,
     "  \"each errors == 0\",\n"
     "  \"median deliveries >= 20\",             # food brought to the nest, over the swarm\n"
     "  \"fraction(deliveries >= 10) >= 0.9\",   # 10 or more in at least 9 runs of 10\n",
     "1500", "the robots fetch food from grey patches and bring it to the black nest in the middle", true},
    {"cpp", nullptr, nullptr,
     "  \"each errors == 0\",\n"
     "  \"median files/spread.csv[shrink].last < 0.6\",             # the spread at least 40% smaller\n"
     "  \"fraction(files/spread.csv[shrink].last < 0.8) >= 0.8\",   # and gathered in 8 runs of 10\n",
     "600", "the robots gather (aggregation, in C++): each steers towards the robots it hears over range-and-bearing",
     false, true},
};
}  // namespace

const std::vector<std::string>& ProjectTemplateNames() {
  static const std::vector<std::string> names = {"empty", "aggregation", "foraging", "cpp"};
  return names;
}

const ProjectTemplate* FindProjectTemplate(const std::string& name) {
  for (const ProjectTemplate& t : kTemplates)
    if (name == t.name) return &t;
  return nullptr;
}

}  // namespace essaim
