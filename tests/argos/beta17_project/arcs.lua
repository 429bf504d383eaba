-- Each robot drives a slow arc, so that the poses the loop functions write change every tick.
function init() end

function step()
  robot.wheels.set_velocity(4, 6)
end

function reset() end

function destroy() end
