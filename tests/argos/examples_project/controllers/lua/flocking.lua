-- The Lua twin of controllers/flocking/flocking.cpp (same arithmetic, same order). Lua
-- controllers read <params> attributes only, so its twin experiment gives them flat.
local velocity, attraction

function init()
  velocity = tonumber(robot.params.velocity)
  attraction = tonumber(robot.params.attraction)
  robot.colored_blob_omnidirectional_camera.enable()
  reset()
end

function reset()
  robot.range_and_bearing.clear_data()
  robot.leds.set_single_color(13, "red")
end

local function heading()
  local q = robot.positioning.orientation
  return math.atan(2.0 * q.w * q.z, 1.0 - 2.0 * q.z * q.z)  -- in (-pi, pi]: the byte sent stays in 0..255
end

function step()
  local yaw = heading()
  robot.range_and_bearing.set_data(1, math.floor((yaw + math.pi) / (2.0 * math.pi) * 255.0))
  local x, y = math.cos(yaw), math.sin(yaw)
  for i = 1, #robot.range_and_bearing do
    local heard = robot.range_and_bearing[i].data[1] / 255.0 * (2.0 * math.pi) - math.pi
    x = x + math.cos(heard)
    y = y + math.sin(heard)
  end
  local align = math.atan(y, x) - yaw
  local tx, ty = math.cos(align), math.sin(align)
  for i = 1, #robot.colored_blob_omnidirectional_camera do
    local blob = robot.colored_blob_omnidirectional_camera[i]
    local c = blob.color
    if c.red == 255 and c.green == 0 and c.blue == 0 and blob.distance > 0 then
      tx = tx + math.cos(blob.angle) * attraction / blob.distance
      ty = ty + math.sin(blob.angle) * attraction / blob.distance
    end
  end
  local turn = math.atan(ty, tx)
  robot.wheels.set_velocity(velocity - velocity * turn, velocity + velocity * turn)
end

function destroy() end
