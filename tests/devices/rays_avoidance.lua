-- Obstacle avoidance with the proximity ring: drive straight; when something is in front,
-- turn on the spot away from the side it is on (ARGoS's diffusion example, vector form).
local speed

function init()
  speed = tonumber(robot.params.speed)
  robot.wheels.set_velocity(speed, speed)
end

function step()
  local x, y = 0, 0
  for i = 1, #robot.proximity do
    local p = robot.proximity[i]
    x = x + p.value * math.cos(p.angle)
    y = y + p.value * math.sin(p.angle)
  end
  local angle = math.atan(y, x)
  if x * x + y * y > 1e-4 and math.abs(angle) < math.pi / 2 then
    if angle > 0 then
      robot.wheels.set_velocity(speed, -speed)  -- obstacle on the left: turn right
    else
      robot.wheels.set_velocity(-speed, speed)
    end
  else
    robot.wheels.set_velocity(speed, speed)
  end
end

function reset() init() end
function destroy() end
