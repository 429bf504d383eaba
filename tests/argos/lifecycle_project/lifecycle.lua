-- Logs the ground under the robot at the first step, and counts steps.
steps = 0

function init() end

function step()
  steps = steps + 1
  if steps == 1 then log("ground " .. robot.motor_ground[1].value) end
end
