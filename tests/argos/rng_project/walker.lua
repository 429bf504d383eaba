-- Drives ahead.
function init() end

function step()
  robot.wheels.set_velocity(5, 5)
end

function reset() end

function destroy() end
