-- The fuzzed bindings are called from the host (fuzz_lua_bindings.cpp); the controller
-- itself does nothing.
function init() end
function step() end
