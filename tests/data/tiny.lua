-- Minimal controller for the sweep tests: drive in a gentle curve.
-- params: speed (wheel speed, cm/s); fail = "1" raises an error in step(), so that a
-- sweep with strict = true has a run that fails (exit 1).
local speed, fail

function init()
  speed = tonumber(robot.params.speed) or 5
  fail = robot.params.fail == "1"
end

function step()
  if fail then
    error("deliberate failure (fail=1)")
  end
  local x = robot.positioning.position.x  -- read a sensor, as real controllers do
  robot.wheels.set_velocity(speed, speed * (x > 0 and 0.8 or 0.9))
end

function reset()
  init()
end

function destroy()
end
