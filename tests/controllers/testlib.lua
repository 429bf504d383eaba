-- Tiny assertion helper for the plain-Lua tests. Each test file:
--   local t = require "testlib"
--   t.test("name", function() t.eq(1, 1) end)
--   t.done()      -- prints "N passed, M failed", exits non-zero on failure
local M = { passed = 0, failed = 0 }

local function fail(msg, level)
  error(msg, (level or 1) + 2)
end

local function show(v)
  if type(v) == "string" then return string.format("%q", v) end
  return tostring(v)
end

function M.ok(cond, msg)
  if not cond then fail("expected true: " .. (msg or "")) end
end

function M.eq(actual, expected, msg)
  if actual ~= expected then
    fail(string.format("expected %s, got %s %s", show(expected), show(actual), msg or ""))
  end
end

function M.near(actual, expected, tol, msg)
  tol = tol or 1e-9
  if type(actual) ~= "number" or math.abs(actual - expected) > tol then
    fail(string.format("expected %s +- %s, got %s %s", show(expected), show(tol), show(actual),
                       msg or ""))
  end
end

function M.raises(fn, pattern, msg)
  local ok, err = pcall(fn)
  if ok then fail("expected an error " .. (msg or "")) end
  if pattern and not tostring(err):find(pattern) then
    fail("error '" .. tostring(err) .. "' does not match '" .. pattern .. "'")
  end
end

function M.test(name, fn)
  local ok, err = xpcall(fn, debug.traceback)
  if ok then
    M.passed = M.passed + 1
  else
    M.failed = M.failed + 1
    io.stderr:write("FAIL " .. name .. ": " .. tostring(err) .. "\n")
  end
end

--- Seeded pseudo-random stub with robot.random's interface: uniform(), uniform(max),
--- uniform(min, max). A 48-bit linear congruential generator (drand48's constants and seeding),
--- reproducible; a few outputs are skipped so that nearby seeds give unrelated first draws.
function M.rng(seed)
  local state = (((seed or 1) << 16) | 0x330E) & 0xFFFFFFFFFFFF
  local r = {}
  local function next01()
    state = (state * 0x5DEECE66D + 0xB) & 0xFFFFFFFFFFFF
    return state / 0x1000000000000
  end
  for _ = 1, 4 do next01() end
  function r.uniform(a, b)
    local u = next01()
    if a == nil then return u end
    if b == nil then return u * a end
    return a + u * (b - a)
  end
  return r
end

function M.done()
  print(string.format("%d passed, %d failed", M.passed, M.failed))
  os.exit(M.failed == 0 and 0 or 1)
end

return M
