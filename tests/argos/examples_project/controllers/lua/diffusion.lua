-- The Lua twin of controllers/diffusion/diffusion.cpp: the same arithmetic in the same order,
-- so that both give bit-identical trajectories.
local straight_min, straight_max, delta, velocity

function init()
  local alpha = tonumber(robot.params.alpha or "10")
  straight_max = alpha * (math.pi / 180)
  straight_min = -straight_max
  delta = tonumber(robot.params.delta or "0.5")
  velocity = tonumber(robot.params.velocity or "2.5")
end

function step()
  local x, y = 0.0, 0.0
  for i = 1, #robot.proximity do
    local r = robot.proximity[i]
    x = x + math.cos(r.angle) * r.value
    y = y + math.sin(r.angle) * r.value
  end
  x = x / #robot.proximity
  y = y / #robot.proximity
  local angle = math.atan(y, x)
  if angle >= straight_min and angle <= straight_max and math.sqrt(x * x + y * y) < delta then
    robot.wheels.set_velocity(velocity, velocity)
  elseif angle > 0 then
    robot.wheels.set_velocity(velocity, 0)
  else
    robot.wheels.set_velocity(0, velocity)
  end
end

function reset() end

function destroy() end
