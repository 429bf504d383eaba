-- Loop functions the fuzzed .argos files may name (script="loop.lua").
local n = 0
function init() end
function pre_step() n = n + 1 end
function post_step()
  if n % 2 == 0 then experiment.timeseries({tick = n}) end
end
function floor_color(x, y) return (x > 0) and "black" or "white" end
function is_experiment_finished() return false end
function post_experiment() return {steps = n} end
function reset() end
function destroy() end
