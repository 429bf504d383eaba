-- Every ray and ground sensor on: proximity-based diffusion (ARGoS's example), the
-- distance scanner rotating, light and ground readings summed as a controller would.
-- Measures the cost of sensing (`essaim bench`, scenario rays-1000).
local speed = 10
seen = 0

function init()
  robot.distance_scanner.set_rpm(60)
  robot.wheels.set_velocity(speed, speed)
end

function step()
  local best, idx = 0, 0
  for i = 1, #robot.proximity do
    local v = robot.proximity[i].value
    if v > best then best, idx = v, i end
  end
  if best == 0 then
    robot.wheels.set_velocity(speed, speed)
  elseif idx <= 12 then
    robot.wheels.set_velocity(speed, -speed)
  else
    robot.wheels.set_velocity(-speed, speed)
  end
  local light = 0
  for i = 1, #robot.light do light = light + robot.light[i].value end
  local ground = robot.motor_ground[1].value + robot.base_ground[1].value
  seen = #robot.distance_scanner.short_range + #robot.distance_scanner.long_range + light + ground
end

function reset() init() end
function destroy() end
