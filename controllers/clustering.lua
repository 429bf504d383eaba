-- Object clustering for the foot-bot: find red LED cylinders with the omnidirectional
-- camera, grip one, carry it to the black zone, let go when it turns blue (the loop
-- functions, arenas/clustering_loop.lua, recolour a cylinder once it is in the zone), back
-- off and search again.
--
-- Devices: differential_steering, footbot_gripper (actuators); colored_blob_omnidirectional_camera,
-- footbot_proximity, positioning (sensors). No LEDs of its own: other robots' cameras see
-- only cylinders. Parameters (<params>, all optional):
--   speed="10"       cm/s when cruising
--   zone="0,0"       x,y (m) of the zone's centre, where loads go
--
-- States: search (random walk, turn towards the nearest red blob), approach (gripper locked,
-- drive onto the target; one gripped at the side is turned under until it is ahead), carry
-- (head for the zone, the load hanging on the gripper's spring), drop (unlocked, turn until the
-- load passes straight ahead: the gripper lets go when its disc touches it), leave (reverse
-- and turn away after a delivery or a miss).

local GRIP_REACH = 14.5    -- cm: a blob this close and dead ahead is touching the gripper
local LOCK_AT = 30         -- cm: lock the gripper this close to the target
local HELD_ANGLE = 0.35    -- rad: a touching target within this of straight ahead is held ahead

local speed, zone_x, zone_y
local state, timer, lost
deliveries = 0             -- global: the loop functions sum it over the swarm (r:lua_global)

local function is_red(b) return b.color.red > 200 and b.color.blue < 50 end
local function is_blue(b) return b.color.blue > 200 and b.color.red < 50 end

-- The nearest blob satisfying `keep`, or nil.
local function nearest(keep)
  local best = nil
  for _, b in ipairs(robot.colored_blob_omnidirectional_camera) do
    if keep(b) and (best == nil or b.distance < best.distance) then best = b end
  end
  return best
end

-- The load in the gripper: the blob nearest `load_distance`, the distance it had when gripped,
-- within 2 cm of it, whatever its colour and bearing (the gripper holds it on a spring from
-- the robot's centre, as ARGoS's: at a distance, not a bearing).
local load_distance = 0
local drop_side = 0  -- the side the load was on while dropping it: -1 right, 1 left
local function load()
  local best = nil
  for _, b in ipairs(robot.colored_blob_omnidirectional_camera) do
    local off = math.abs(b.distance - load_distance)
    if off < 2 and (best == nil or off < math.abs(best.distance - load_distance)) then best = b end
  end
  return best
end

-- Wheel speeds steering towards `angle` (rad, robot frame) at `v` cm/s.
local function steer(angle, v)
  local turn = math.max(-1, math.min(1, angle / (math.pi / 2)))
  robot.wheels.set_velocity(v * (1 - turn), v * (1 + turn))
end

-- Largest proximity reading in front (±60°), and the side it is on.
local function front_obstacle()
  local value, angle = 0, 0
  for _, p in ipairs(robot.proximity) do
    if math.abs(p.angle) < math.pi / 3 and p.value > value then value, angle = p.value, p.angle end
  end
  return value, angle
end

local function random_walk()
  local value, angle = front_obstacle()
  if value > 0.2 then
    steer(angle > 0 and -math.pi / 2 or math.pi / 2, speed / 2)  -- turn away
  elseif timer <= 0 then
    timer = math.floor(robot.random.uniform(10, 40))
    local turn = robot.random.uniform(-0.6, 0.6)
    robot.wheels.set_velocity(speed * (1 - turn), speed * (1 + turn))
  end
end

local function go(next_state, ticks)
  state, timer, lost = next_state, ticks or 0, 0
end

function init()
  speed = tonumber(robot.params.speed or "10")
  local zx, zy = (robot.params.zone or "0,0"):match("([^,]+),([^,]+)")
  zone_x, zone_y = tonumber(zx), tonumber(zy)
  robot.colored_blob_omnidirectional_camera.enable()
  robot.gripper.unlock()
  deliveries = 0
  go("search")
end

function step()
  timer = timer - 1
  if state == "search" then
    local target = nearest(is_red)
    if target then
      steer(target.angle, speed)
      if target.distance < LOCK_AT then
        robot.gripper.lock_positive()
        go("approach", 60)
      end
    else
      random_walk()
    end
  elseif state == "approach" then
    local target = nearest(is_red)
    if target == nil or timer <= 0 then
      robot.gripper.unlock()
      go("leave", 15)
    elseif target.distance < GRIP_REACH and math.abs(target.angle) < HELD_ANGLE then
      load_distance = target.distance
      go("carry")  -- locked and touching: the gripper holds it from this tick's act on
    elseif target.distance < GRIP_REACH then
      -- Gripped at the side: turn in place under it until it is ahead.
      local side = target.angle > 0 and 1 or -1
      robot.wheels.set_velocity(-speed / 4 * side, speed / 4 * side)
    else
      steer(target.angle, speed / 2)
    end
  elseif state == "carry" then
    local held = load()
    if held == nil then
      lost = lost + 1
      if lost > 5 then robot.gripper.unlock() go("search") end  -- dropped it
    elseif is_blue(held) then
      robot.gripper.unlock()  -- delivered: the loop functions turned it blue
      deliveries = deliveries + 1
      drop_side = 0
      go("drop", 60)
      return
    else
      lost = 0
    end
    local p = robot.positioning.position
    local yaw = robot.positioning.orientation:toeulerangles()
    local bearing = math.atan(zone_y - p.y, zone_x - p.x) - yaw
    bearing = math.atan(math.sin(bearing), math.cos(bearing))
    steer(bearing, speed)
  elseif state == "drop" then
    -- An unlocked gripper lets go when its disc, in front, touches the load: turn until the
    -- load passes straight ahead.
    local held = load()
    local side = held and (held.angle > 0 and 1 or -1) or 0
    if held == nil or timer <= 0 or (drop_side ~= 0 and side ~= drop_side) then
      robot.wheels.set_velocity(0, 0)
      go("leave", 25)
    else
      drop_side = side
      robot.wheels.set_velocity(-speed / 4 * side, speed / 4 * side)
    end
  elseif state == "leave" then
    if timer > 12 then robot.wheels.set_velocity(-speed, -speed)
    elseif timer > 0 then robot.wheels.set_velocity(speed, -speed)
    else go("search") end
  end
end

function reset() init() end
function destroy() end
