-- The students' controller: drive ahead, count steps, keep the ground reading in globals
-- that the loop functions read from the controller's Lua state.
steps = 0
ground = -1

function init() end

function step()
  steps = steps + 1
  ground = robot.motor_ground[1].value
  robot.wheels.set_velocity(0, 0)
end

function reset() end

function destroy() end
