-- Turns the ARGoS `robot` table into the behaviour's percepts (units of the report: cm, rad,
-- battery units 0..100). Missing devices read as "nothing": no scanner readings, no messages,
-- a full battery, a white floor.
local geometry = require "foraging.geometry"

local M = {}

local EMPTY = {}

--- Percepts at step `tick` (the controller's own step counter).
function M.percepts(robot, tick)
  local p = { tick = tick }
  local pos = robot.positioning and robot.positioning.position
  if pos then
    p.x, p.y = pos.x * 100, pos.y * 100
    p.yaw = geometry.yaw_of(robot.positioning.orientation)
  else
    p.x, p.y, p.yaw = 0, 0, 0
  end
  p.battery = robot.battery and robot.battery.available_charge * 100 or 100
  p.ground = robot.base_ground or EMPTY
  p.proximity = robot.proximity or EMPTY
  local ds = robot.distance_scanner
  p.short = ds and ds.short_range or EMPTY
  p.long = ds and ds.long_range or EMPTY
  local messages = {}
  local rab = robot.range_and_bearing
  if rab then
    for i = 1, #rab do messages[i] = rab[i].data end
  end
  p.messages = messages
  return p
end

return M
