local dir = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
package.path = dir .. "/?.lua;" .. dir .. "/../../controllers/?.lua;" .. package.path
local t = require "testlib"
local ground = require "foraging.ground"

local function readings(...)
  local out = {}
  for i, v in ipairs({ ... }) do out[i] = { value = v } end
  return out
end

t.test("see / inside black", function()
  local see, inside = ground.read(readings(1, 1, 1, 1, 1, 1, 1, 1))
  t.ok(not see); t.ok(not inside)
  see, inside = ground.read(readings(1, 0, 1, 1, 1, 1, 1, 1))
  t.ok(see); t.ok(not inside)
  see, inside = ground.read(readings(0, 0, 0, 0, 0, 0, 0, 0))
  t.ok(see); t.ok(inside)
  see, inside = ground.read({ 0, 0, 0 })
  t.ok(see and inside, "plain numbers work too")
  see, inside = ground.read({})
  t.ok(not see and not inside, "no sensor")
end)

t.test("nest or source from the distance to the nest", function()
  t.eq(ground.classify(false, 10, 50, 20, 40), nil)
  t.eq(ground.classify(true, 10, 50, 20, 40), "nest")
  t.eq(ground.classify(true, 70, 50, 20, 40), "nest")
  t.eq(ground.classify(true, 80, 50, 20, 40), nil, "ambiguous band")
  t.eq(ground.classify(true, 90, 50, 20, 40), "source")
  t.eq(ground.classify(true, 300, 50, 20, 40), "source")
end)

t.done()
