-- Range-and-bearing load: broadcast a step counter, read every received message.
n = 0
function init() robot.wheels.set_velocity(10, 10) end
function step()
  n = n + 1
  robot.range_and_bearing.set_data(1, n % 256)
  local s = 0
  for i = 1, #robot.range_and_bearing do
    local m = robot.range_and_bearing[i]
    s = s + m.range * m.horizontal_bearing + m.data[1]
  end
end
function reset() end
function destroy() end
