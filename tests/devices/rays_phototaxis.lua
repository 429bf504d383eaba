-- Phototaxis: steer towards the light (the light ring's readings as a vector), turn away
-- from anything close in front (the proximity ring), wander when no light is seen.
local speed

local function ring_vector(ring)
  local x, y = 0, 0
  for i = 1, #ring do
    x = x + ring[i].value * math.cos(ring[i].angle)
    y = y + ring[i].value * math.sin(ring[i].angle)
  end
  return x, y
end

function init()
  speed = tonumber(robot.params.speed)
end

function step()
  local ox, oy = ring_vector(robot.proximity)
  local obstacle = math.atan(oy, ox)
  if ox * ox + oy * oy > 1e-2 and math.abs(obstacle) < math.pi / 2 then
    if obstacle > 0 then robot.wheels.set_velocity(speed, -speed) else robot.wheels.set_velocity(-speed, speed) end
    return
  end
  local lx, ly = ring_vector(robot.light)
  if lx == 0 and ly == 0 then
    robot.wheels.set_velocity(speed, speed)
    return
  end
  local a = math.atan(ly, lx)  -- bearing of the light, rad
  local turn = math.max(-1, math.min(1, a / (math.pi / 4)))
  robot.wheels.set_velocity(speed * (1 - turn), speed * (1 + turn))
end

function reset() end
function destroy() end
