-- Distance-scanner readings grouped into directions (report 4.3, listing 4.3), pure functions.
--
-- A table groups the scanner's readings into n equal angular sectors ("directions") covering the
-- whole turn; sector k (1..n) is centred on -pi + pi/n + (k - 1) * 2pi/n. Each step, a sector that
-- got readings takes the least optimistic (smallest) of them; a sector without new readings keeps
-- its last value, since the rotating scanner only sweeps part of the turn per step.
--
-- Angles are stored in a frame chosen by the caller through `offset`, added to each reading's
-- angle: offset 0 keeps the robot frame (the report); the robot's yaw gives world-frame sectors,
-- which stay valid while the robot turns between two sweeps (see foraging.lua).
local geometry = require "foraging.geometry"

local M = {}

local pi = math.pi

--- Centre angle of sector k of an n-sector table.
function M.centre(k, n)
  return -pi + pi / n + (k - 1) * 2 * pi / n
end

--- New table of n sectors, all `free` (nothing seen). Each sector keeps its value (cm), the
--- angle of the reading that gave it (table frame) and the step of its last refresh.
function M.new(n, free)
  local t = { n = n, free = free, value = {}, angle = {}, stamp = {} }
  for k = 1, n do t.value[k] = free; t.angle[k] = M.centre(k, n); t.stamp[k] = 0 end
  return t
end

--- Sector (1..n) holding angle a.
function M.sector(a, n)
  local k = math.floor((geometry.wrap(a) + pi) / (2 * pi / n)) + 1
  if k > n then k = n elseif k < 1 then k = 1 end
  return k
end

--- Distance in cm meant by one reading: -2 (nothing in range) -> free, -1 (too close) -> 0.
function M.reading_value(distance, free)
  if distance == -2 then return free end
  if distance < 0 then return 0 end
  if distance > free then return free end
  return distance
end

--- Refreshes table t with this step's readings (array of {angle, distance}); `step` is any
--- increasing step counter. Returns t.
function M.update(t, readings, offset, step)
  offset = offset or 0
  local n, value, angle, stamp = t.n, t.value, t.angle, t.stamp
  for i = 1, #readings do
    local r = readings[i]
    local a = r.angle + offset
    local k = M.sector(a, n)
    local v = M.reading_value(r.distance, t.free)
    if stamp[k] ~= step or v < value[k] then
      value[k] = v
      angle[k] = a
      stamp[k] = step
    end
  end
  return t
end

--- Closest obstacle of the table. Only readings whose angle, brought back to the robot frame
--- (angle - offset), lies within `max_angle` of the front count (default: all). Ties go to the
--- most frontal one. Returns distance (t.free when nothing), angle in the robot frame (that of
--- the reading itself, not its sector's centre: an obstacle dead ahead keeps its side).
function M.closest(t, offset, max_angle)
  offset = offset or 0
  max_angle = max_angle or pi
  local best, best_angle = t.free, 0
  for k = 1, t.n do
    local rel = geometry.wrap(t.angle[k] - offset)
    if math.abs(rel) <= max_angle then
      local v = t.value[k]
      if v < best or (v == best and v < t.free and math.abs(rel) < math.abs(best_angle)) then
        best, best_angle = v, rel
      end
    end
  end
  return best, best_angle
end

--- Greedy choice (report 4.3, listing 4.6): among the sectors where the obstacle is farthest (or
--- absent), the one closest to the goal direction `goal` (same frame as the table). Obstacles
--- beyond the goal do not matter: with `goal_distance` given, sector values are capped to it.
--- When the goal's own sector is among the best, the goal direction itself is returned rather
--- than the sector's centre, so an unobstructed robot heads straight for its goal.
--- Returns the chosen direction (table frame) and its value.
function M.best_direction(t, goal, goal_distance)
  local cap = goal_distance or t.free
  local n = t.n
  local best_value, best_k, best_gap = -1, nil, nil
  for k = 1, n do
    local v = t.value[k]
    if v > cap then v = cap end
    local gap = math.abs(geometry.wrap(M.centre(k, n) - goal))
    if v > best_value or (v == best_value and gap < best_gap) then
      best_value, best_k, best_gap = v, k, gap
    end
  end
  local goal_k = M.sector(goal, n)
  local goal_v = t.value[goal_k]
  if goal_v > cap then goal_v = cap end
  if goal_v >= best_value then
    return geometry.wrap(goal), goal_v
  end
  return M.centre(best_k, n), best_value
end

return M
