-- The controller the fuzzed .argos files name (script="fuzz.lua"): touches every device
-- it may have been given, so that what the loader built is also exercised.
local t = 0
function init() end
function step()
  t = t + 1
  local r = robot
  if r.wheels then r.wheels.set_velocity(5 + t % 7, 5) end
  if r.leds then r.leds.set_all_colors(t % 2 == 0 and "red" or "green") end
  if r.range_and_bearing then r.range_and_bearing.set_data(1, t % 256) end
  if r.proximity then local _ = #r.proximity end
  if r.distance_scanner then r.distance_scanner.enable() end
  if r.colored_blob_omnidirectional_camera then r.colored_blob_omnidirectional_camera.enable() end
  if r.gripper then r.gripper.lock_positive() end
  if r.turret then r.turret.set_rotation(t / 10) end
end
function reset() end
function destroy() end
