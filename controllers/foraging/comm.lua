-- Source messages over range-and-bearing (report 6.2.1), pure functions.
--
-- A message is 10 bytes: type (1 = source position), sign x, sign y, hundreds of |x|,
-- hundreds of |y|, rest of |x|, rest of |y|, then zeros. Positions are in centimetres, rounded to
-- the nearest centimetre; signs are 0 for zero, 1 for positive, 2 for negative (listing 6.15's
-- intent). |x| and |y| up to 25599 cm fit; larger values are clamped.
local M = {}

M.TYPE_SOURCE = 1
M.SIZE = 10
M.MAX_ABS = 255 * 100 + 99

local function split(v)
  local n = math.floor(math.abs(v) + 0.5)
  if n > M.MAX_ABS then n = M.MAX_ABS end
  local sign = 0
  if n > 0 then sign = (v > 0) and 1 or 2 end
  return sign, n // 100, n % 100
end

--- Message (array of 10 integers 0..255) announcing a source at (x, y) cm.
function M.encode(x, y)
  local sx, hx, rx = split(x)
  local sy, hy, ry = split(y)
  return { M.TYPE_SOURCE, sx, sy, hx, hy, rx, ry, 0, 0, 0 }
end

local function byte(v)
  v = tonumber(v)
  if v == nil then return nil end
  return math.floor(v + 0.5)
end

--- Decodes a received message (robot.range_and_bearing[i].data, bytes as integers or floats).
--- Returns x, y in cm, or nil when it is not a well-formed source message.
function M.decode(data)
  if data == nil or #data < 7 then return nil end
  if byte(data[1]) ~= M.TYPE_SOURCE then return nil end
  local sx, sy = byte(data[2]), byte(data[3])
  if (sx ~= 0 and sx ~= 1 and sx ~= 2) or (sy ~= 0 and sy ~= 1 and sy ~= 2) then return nil end
  local x = 100 * byte(data[4]) + byte(data[6])
  local y = 100 * byte(data[5]) + byte(data[7])
  if sx == 2 then x = -x end
  if sy == 2 then y = -y end
  return x, y
end

--- Which known source to broadcast at step `tick`: all of them in turn (algorithm 6.2).
--- Returns an index into a list of `count` sources, or nil when there is none.
function M.index_to_broadcast(tick, count)
  if count < 1 then return nil end
  return (tick % count) + 1
end

return M
