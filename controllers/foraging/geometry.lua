-- Angles and planar geometry (pure functions).
local M = {}

local pi = math.pi

--- Wraps an angle into [-pi, pi).
function M.wrap(a)
  a = (a + pi) % (2 * pi)
  return a - pi
end

--- World-frame direction (rad) from (x, y) to (gx, gy).
function M.direction(x, y, gx, gy)
  return math.atan(gy - y, gx - x)
end

function M.distance(x, y, gx, gy)
  local dx, dy = gx - x, gy - y
  return math.sqrt(dx * dx + dy * dy)
end

--- Angle of the goal seen from the robot (0 = ahead, > 0 = to the left), in [-pi, pi).
function M.relative_angle(x, y, yaw, gx, gy)
  return M.wrap(M.direction(x, y, gx, gy) - yaw)
end

--- Yaw (rad) from an ARGoS orientation: a quaternion userdata offering toeulerangles() or
--- toangleaxis(), or the old plain-table form {angle=, axis={z=}}.
function M.yaw_of(q)
  if q == nil then return 0 end
  if q.toeulerangles then
    local z = q:toeulerangles()
    return z
  end
  if q.toangleaxis then
    local angle, axis = q:toangleaxis()
    if axis.z < 0 then angle = -angle end
    return M.wrap(angle)
  end
  local angle = q.angle or 0
  if q.axis and q.axis.z < 0 then angle = -angle end
  return M.wrap(angle)
end

return M
