-- Camera load: all LEDs lit, read every blob each step.
n = 0
function init()
  robot.wheels.set_velocity(10, 10)
  robot.leds.set_all_colors("green")
  robot.colored_blob_omnidirectional_camera.enable()
end
function step()
  n = n + 1
  local s = 0
  for i = 1, #robot.colored_blob_omnidirectional_camera do
    local b = robot.colored_blob_omnidirectional_camera[i]
    s = s + b.distance * b.angle + b.color.green
  end
end
function reset() end
function destroy() end
