function init() end

function step() robot.wheels.set_velocity(0, 0) end
