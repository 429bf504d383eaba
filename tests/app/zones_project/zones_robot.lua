function init() end
function step() robot.wheels.set_velocity(4, 4) end
