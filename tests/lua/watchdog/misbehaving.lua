-- One script, five behaviours chosen by the controller's `mode` parameter
-- (watchdog_test.py): good robots drive straight; the others misbehave in step().
local mode = robot.params.mode
local start

function init()
  start = robot.positioning.position
end

function step()
  if mode == "good" then
    robot.wheels.set_velocity(5, 5)
  elseif mode == "loop" then
    -- Never ends: the sum only grows (it would take 2^62 iterations to wrap).
    local x = 1
    while x > 0 do x = x + 2 end
  elseif mode == "nan" then
    robot.wheels.set_velocity(0 / 0, 5)
  elseif mode == "huge" then
    robot.wheels.set_velocity(1e300, -1e300)
  elseif mode == "hog" then
    local t = {}
    while true do t[#t + 1] = string.rep("x", 1000) .. #t end
  end
end

function destroy()
  local p = robot.positioning.position
  log("moved ", robot.id, " ", math.sqrt((p.x - start.x) ^ 2 + (p.y - start.y) ^ 2))
end
