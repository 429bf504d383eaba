-- A controller that does nothing: robots that stand still (a <lua_controller> needs a script).
function init() end
function step() end
function reset() end
function destroy() end
