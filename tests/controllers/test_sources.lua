local dir = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
package.path = dir .. "/?.lua;" .. dir .. "/../../controllers/?.lua;" .. package.path
local t = require "testlib"
local sources = require "foraging.sources"

t.test("originality check (ORGN_SRC_DST)", function()
  local list = {}
  t.ok(sources.is_original(list, 0, 0, 80), "empty list")
  t.eq(sources.add(list, 100, 100, 80, 1), 1)
  t.ok(not sources.is_original(list, 150, 150, 80), "70.7 cm away")
  t.ok(not sources.is_original(list, 180, 100, 80), "exactly 80 cm is not original")
  t.ok(sources.is_original(list, 180.5, 100, 80), "80.5 cm away")
  t.eq(sources.add(list, 130, 100, 80, 1), nil, "duplicate refused")
  t.eq(sources.add(list, -300, 0, 80, 1), 2)
  t.ok(not sources.is_original(list, -310, 20, 80), "close to the second one")
end)

t.test("quality score = trips / battery spent, new sources optimistic", function()
  local s = sources.new(0, 0, 1)
  t.eq(s.score, 1)
  sources.record_trip(s, 20)
  t.near(s.score, 1 / 20)
  sources.record_trip(s, 30)
  t.near(s.score, 2 / 50)
  sources.record_abort(s)
  t.near(s.score, 2 / 150, 1e-12, "a trip given up is charged a whole battery")
  t.eq(s.trips, 2); t.eq(s.spent, 150)
  t.eq(sources.score(3, 0), nil)
  local z = sources.new(0, 0, 1)
  sources.record_trip(z, 0)
  t.eq(z.score, 1, "no battery spent yet keeps the initial score")
end)

t.test("best source, first on ties without a random source", function()
  local list = { sources.new(0, 0, 0.2), sources.new(0, 0, 0.5), sources.new(0, 0, 0.5) }
  t.eq(sources.best(list), 2)
  t.eq(sources.best({}), nil)
end)

t.test("best source: ties drawn uniformly, a lone best never loses", function()
  local list = { sources.new(0, 0, 0.5), sources.new(0, 0, 0.2), sources.new(0, 0, 0.5),
                 sources.new(0, 0, 0.5) }
  local rng = t.rng(7)
  local count = { 0, 0, 0, 0 }
  local n = 30000
  for _ = 1, n do
    local k = sources.best(list, rng.uniform)
    count[k] = count[k] + 1
  end
  t.eq(count[2], 0, "not among the best")
  for _, k in ipairs({ 1, 3, 4 }) do t.near(count[k] / n, 1 / 3, 0.015, "tie " .. k) end
  local seq, i = { 0, 0.999999, 1 }, 0
  local function u() i = i + 1; return seq[i] end
  t.eq(sources.best(list, u), 1, "u = 0: the first of the ties")
  t.eq(sources.best(list, u), 4, "u just below 1: the last one")
  t.eq(sources.best(list, u), 4, "u = 1 stays in range")
  list[2].score = 0.9
  for _ = 1, 100 do t.eq(sources.best(list, rng.uniform), 2) end
end)

t.test("a swarm that knows the sources, all scored 1, spreads its first picks over them", function()
  local first = { 0, 0, 0 }
  for seed = 1, 3000 do
    local list = { sources.new(-250, 0, 1), sources.new(400, 350, 1), sources.new(420, -420, 1) }
    local k = sources.choose(list, 0.1, t.rng(seed).uniform)
    first[k] = first[k] + 1
  end
  for k = 1, 3 do t.near(first[k] / 3000, 1 / 3, 0.04, "source " .. k) end
end)

t.test("a trip given up costs a whole battery: a far source that sends robots home scores low", function()
  local near, far = sources.new(-250, 0, 1), sources.new(400, 350, 1)
  sources.record_trip(near, 15)
  sources.record_abort(far)
  t.eq(far.trips, 0); t.eq(far.spent, 100); t.eq(far.score, 0)
  sources.record_trip(far, 35)
  t.near(far.score, 1 / 135)
  t.eq(sources.best({ near, far }), 1)
  -- a jammed near source given up twice falls behind the far one
  sources.record_abort(near); sources.record_abort(near)
  t.near(near.score, 1 / 215)
  sources.record_trip(far, 35)
  t.eq(sources.best({ near, far }), 2)
end)

t.test("epsilon-greedy: empty and single lists", function()
  local rng = t.rng(1)
  t.eq(sources.choose({}, 0.1, rng.uniform), nil)
  local one = { sources.new(0, 0, 0.1) }
  for _ = 1, 20 do t.eq(sources.choose(one, 0.9, rng.uniform), 1) end
end)

t.test("epsilon-greedy frequencies: best with 1 - eps, others uniformly", function()
  local list = {}
  local scores = { 0.02, 0.05, 0.5, 0.01, 0.03 }
  for i, s in ipairs(scores) do list[i] = sources.new(i, i, s) end
  for _, eps in ipairs({ 0.1, 0.3 }) do
    local rng = t.rng(12345)
    local n = 100000
    local count = { 0, 0, 0, 0, 0 }
    for _ = 1, n do
      local k = sources.choose(list, eps, rng.uniform)
      count[k] = count[k] + 1
    end
    -- binomial standard deviations are ~ 0.001 - 0.0015 here: 5 sigma tolerance
    t.near(count[3] / n, 1 - eps, 0.008, "best, eps=" .. eps)
    for _, k in ipairs({ 1, 2, 4, 5 }) do
      t.near(count[k] / n, eps / 4, 0.006, "other " .. k .. ", eps=" .. eps)
    end
  end
end)

t.test("epsilon-greedy with eps = 0 always exploits, eps = 1 never", function()
  local list = { sources.new(0, 0, 0.1), sources.new(0, 0, 0.9), sources.new(0, 0, 0.3) }
  local rng = t.rng(99)
  for _ = 1, 1000 do t.eq(sources.choose(list, 0, rng.uniform), 2) end
  for _ = 1, 1000 do t.ok(sources.choose(list, 1, rng.uniform) ~= 2) end
end)

t.test("epsilon-greedy draws at the edges of [0, 1]", function()
  local list = { sources.new(0, 0, 0.1), sources.new(0, 0, 0.9), sources.new(0, 0, 0.3) }
  local seq, i = { 0, 1 }, 0
  local function u() i = i + 1; return seq[i] end
  t.eq(sources.choose(list, 0.5, u), 3, "u = 1 picks the last of the others")
  seq, i = { 0, 0 }, 0
  t.eq(sources.choose(list, 0.5, u), 1, "u = 0 picks the first of the others")
end)

t.done()
