local dir = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
package.path = dir .. "/?.lua;" .. dir .. "/../../controllers/?.lua;" .. package.path
local t = require "testlib"
local comm = require "foraging.comm"

local function check_bytes(msg)
  t.eq(#msg, 10, "length")
  for i = 1, 10 do
    t.eq(math.type(msg[i]), "integer", "byte " .. i .. " is an integer")
    t.ok(msg[i] >= 0 and msg[i] <= 255, "byte " .. i .. " in 0..255")
  end
end

t.test("layout of the report's table", function()
  local m = comm.encode(-234, 467)
  t.eq(m[1], 1); t.eq(m[2], 2); t.eq(m[3], 1)
  t.eq(m[4], 2); t.eq(m[5], 4); t.eq(m[6], 34); t.eq(m[7], 67)
  t.eq(m[8], 0); t.eq(m[9], 0); t.eq(m[10], 0)
  check_bytes(m)
end)

t.test("zero has sign byte 0", function()
  local m = comm.encode(0, -0.3)
  t.eq(m[2], 0); t.eq(m[3], 0)
  local x, y = comm.decode(m)
  t.eq(x, 0); t.eq(y, 0)
end)

t.test("'rest y' uses y (the report's table says x)", function()
  local m = comm.encode(11, 99)
  t.eq(m[6], 11); t.eq(m[7], 99)
end)

t.test("round trip over a grid, negatives, zero and +-499", function()
  local values = { -499, -450, -301, -300, -299, -100, -99, -1, 0, 1, 99, 100, 101, 250, 499 }
  for v = -499, 499, 7 do values[#values + 1] = v end
  for _, x in ipairs(values) do
    for _, y in ipairs(values) do
      local m = comm.encode(x, y)
      check_bytes(m)
      local dx, dy = comm.decode(m)
      t.eq(dx, x, "x"); t.eq(dy, y, "y")
    end
  end
end)

t.test("non-integer positions round to the nearest cm", function()
  local rng = t.rng(7)
  for _ = 1, 2000 do
    local x, y = rng.uniform(-500, 500), rng.uniform(-500, 500)
    local m = comm.encode(x, y)
    check_bytes(m)
    local dx, dy = comm.decode(m)
    t.ok(math.abs(dx - x) <= 0.5 + 1e-9, "x within half a cm")
    t.ok(math.abs(dy - y) <= 0.5 + 1e-9, "y within half a cm")
  end
  -- 199.6 rounds to 200, not to 1 hundred + rest 100
  local m = comm.encode(199.6, -99.5)
  t.eq(m[4], 2); t.eq(m[6], 0)
  t.eq(m[5], 1); t.eq(m[7], 0)
end)

t.test("decode accepts float bytes (ARGoS pushes numbers as floats)", function()
  local x, y = comm.decode({ 1.0, 2.0, 1.0, 3.0, 0.0, 5.0, 42.0, 0.0, 0.0, 0.0 })
  t.eq(x, -305); t.eq(y, 42)
end)

t.test("decode rejects other messages", function()
  t.eq(comm.decode({ 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 }), nil, "empty payload")
  t.eq(comm.decode({ 2, 1, 1, 1, 1, 1, 1, 0, 0, 0 }), nil, "other type")
  t.eq(comm.decode({ 1, 3, 1, 1, 1, 1, 1, 0, 0, 0 }), nil, "bad sign")
  t.eq(comm.decode({ 1, 1 }), nil, "too short")
  t.eq(comm.decode(nil), nil, "nil")
end)

t.test("huge values are clamped, still valid bytes", function()
  local m = comm.encode(1e9, -1e9)
  check_bytes(m)
  local x, y = comm.decode(m)
  t.eq(x, comm.MAX_ABS); t.eq(y, -comm.MAX_ABS)
end)

t.test("sources are broadcast in turn", function()
  t.eq(comm.index_to_broadcast(5, 0), nil)
  local seen = {}
  for tick = 1, 6 do seen[#seen + 1] = comm.index_to_broadcast(tick, 3) end
  t.eq(table.concat(seen, ","), "2,3,1,2,3,1")
end)

t.done()
