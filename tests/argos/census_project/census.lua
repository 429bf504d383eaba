-- Globals the census loop functions read from the controller's Lua state.
counter = 42
state = {energy = 7.5}

function init() end

function step() robot.wheels.set_velocity(0, 0) end
