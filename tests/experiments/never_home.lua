-- A controller that never goes home: it wanders (straight lines, turning away from obstacles it
-- feels with the proximity ring) and keeps clear of the nest, so the foraging loop functions
-- never refill it. Used to check that a robot dies when its battery runs out.
-- Devices: differential_steering, positioning, footbot_proximity (optional). Params (optional, metres):
-- NEST_X, NEST_Y, AVOID_NEST (stay this far from the nest centre, default 1.2).
local speed = 30
local nest_x, nest_y, keep_out

function init()
  local p = robot.params or {}
  nest_x = tonumber(p.NEST_X or "") or 0
  nest_y = tonumber(p.NEST_Y or "") or 0
  keep_out = tonumber(p.AVOID_NEST or "") or 1.2
end

local function wrap(a) return (a + math.pi) % (2 * math.pi) - math.pi end

function step()
  -- obstacle felt: spin away from it
  local best, best_angle = 0, 0
  for i = 1, #(robot.proximity or {}) do
    local r = robot.proximity[i]
    if r.value > best then best, best_angle = r.value, r.angle end
  end
  if best > 0 then
    if best_angle >= 0 then robot.wheels.set_velocity(speed, -speed)
    else robot.wheels.set_velocity(-speed, speed) end
    return
  end
  -- too close to the nest: head straight away from it
  local pos = robot.positioning.position
  local dx, dy = pos.x - nest_x, pos.y - nest_y
  if dx * dx + dy * dy < keep_out * keep_out then
    local yaw = robot.positioning.orientation:toeulerangles()
    local rel = wrap(math.atan(dy, dx) - yaw)
    robot.wheels.set_velocity(speed - 20 * rel, speed + 20 * rel)
    return
  end
  robot.wheels.set_velocity(speed, speed)
end

function reset() init() end
function destroy() end
