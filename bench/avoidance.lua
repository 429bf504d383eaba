-- Proximity-based obstacle avoidance, as ARGoS's diffusion examples: sum the 24 proximity
-- vectors; turn away when something is close, else drive straight. Builds a small table per
-- sensor like those examples do, so the Lua cost is a real controller's.
function step()
  local acc = { x = 0, y = 0 }
  for i = 1, 24 do
    local p = robot.proximity[i]
    local v = { x = p.value * math.cos(p.angle), y = p.value * math.sin(p.angle) }
    acc.x = acc.x + v.x
    acc.y = acc.y + v.y
  end
  local length = math.sqrt(acc.x * acc.x + acc.y * acc.y)
  local angle = math.atan(acc.y, acc.x)
  if length > 0.2 then
    local s = math.max(0.5, math.cos(angle)) * 15
    if angle > 0 then robot.wheels.set_velocity(s, 0) else robot.wheels.set_velocity(0, s) end
  else
    robot.wheels.set_velocity(15, 15)
  end
end
