-- The cheapest useful controller: drive straight. Measures the simulator's own overhead.
function init() robot.wheels.set_velocity(10, 10) end
function step() end
function reset() end
function destroy() end
