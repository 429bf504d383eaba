-- The Lua twin of controllers/ground_forager/ground_forager.cpp (same decisions, same order);
-- it reports its finds to nobody (Lua controllers cannot reach C++ loop functions).
local velocity, pause_ticks
local pause, finds, on_spot = 0, 0, false

function init()
  velocity = tonumber(robot.params.velocity or "10")
  pause_ticks = tonumber(robot.params.pause or "10")
  reset()
end

function reset()
  pause, finds, on_spot = 0, 0, false
end

local function found_spot()
  local black, light = false, true
  for i = 1, #robot.motor_ground do
    if robot.motor_ground[i].value < 0.25 then black = true end
    if robot.motor_ground[i].value < 0.75 then light = false end
  end
  if black and not on_spot then
    on_spot = true
    return true
  end
  if light then on_spot = false end
  return false
end

function step()
  if pause > 0 then
    pause = pause - 1
    robot.wheels.set_velocity(0, 0)
    return
  end
  if found_spot() then
    finds = finds + 1
    pause = pause_ticks
    robot.wheels.set_velocity(0, 0)
    return
  end
  local left, right = 0, 0
  for i = 1, #robot.proximity do
    local r = robot.proximity[i]
    if r.angle > 0 and r.angle < 1.2 and r.value > left then left = r.value end
    if r.angle < 0 and r.angle > -1.2 and r.value > right then right = r.value end
  end
  if left < 0.05 and right < 0.05 then
    robot.wheels.set_velocity(velocity, velocity)
  elseif left > right then
    robot.wheels.set_velocity(velocity, -velocity)
  else
    robot.wheels.set_velocity(-velocity, velocity)
  end
end

function destroy() end
