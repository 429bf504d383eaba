-- Known sources: originality, quality score, epsilon-greedy choice (report 6.1.3, annex 6.C).
-- Pure functions over a plain list of sources {x, y (cm), trips, spent, score}.
local M = {}

--- New source record at (x, y) cm with the optimistic initial score.
function M.new(x, y, init_score)
  return { x = x, y = y, trips = 0, spent = 0, score = init_score }
end

--- True when (x, y) is farther than `min_distance` cm from every known source (listing 6.5).
function M.is_original(list, x, y, min_distance)
  for i = 1, #list do
    local s = list[i]
    local dx, dy = s.x - x, s.y - y
    if math.sqrt(dx * dx + dy * dy) <= min_distance then return false end
  end
  return true
end

--- Adds a source if it is original. Returns its index, or nil when it was already known.
function M.add(list, x, y, min_distance, init_score)
  if not M.is_original(list, x, y, min_distance) then return nil end
  list[#list + 1] = M.new(x, y, init_score)
  return #list
end

--- Quality score: trips made to the source per battery unit spent on them. A source that has cost
--- nothing yet keeps its current (initial) score.
function M.score(trips, spent)
  if spent <= 0 then return nil end
  return trips / spent
end

--- Records a completed trip that cost `spent` battery units; updates the score (listing 6.11).
function M.record_trip(src, spent)
  src.trips = src.trips + 1
  src.spent = src.spent + math.max(spent, 0)
  src.score = M.score(src.trips, src.spent) or src.score
end

--- Battery units charged to a source for a trip given up (see record_abort).
M.ABORT_COST = 100

--- Records an abandoned trip (the robot had to go home for its battery): no trip is made and a
--- whole battery is charged, as the report's listing 6.9 does (evalSource(sourceId, 0), i.e.
--- 100 - 0 units), whatever the robot had spent so far: a source that sends robots home empty
--- handed, being far or jammed, should lose its appeal fast.
function M.record_abort(src)
  src.spent = src.spent + M.ABORT_COST
  src.score = M.score(src.trips, src.spent) or src.score
end

--- Index of the best-scored source, nil for an empty list. Ties go to one of them drawn with
--- `uniform()` (in [0, 1]), or to the first one when `uniform` is nil. The report does not say
--- (listing 6.10 calls a placeMaxAtOne it does not show); the first one would send a whole swarm
--- that knows the sources, all scored 1, to the first source of its list at once.
function M.best(list, uniform)
  local best_i, best_s, ties = nil, -math.huge, 0
  for i = 1, #list do
    local sc = list[i].score
    if sc > best_s then best_i, best_s, ties = i, sc, 1
    elseif sc == best_s then ties = ties + 1 end
  end
  if uniform == nil or ties < 2 then return best_i end
  local k = math.min(math.floor(uniform() * ties), ties - 1)
  for i = best_i, #list do
    if list[i].score == best_s then
      if k == 0 then return i end
      k = k - 1
    end
  end
  return best_i
end

--- Epsilon-greedy choice (algorithm 6.1): the best source with probability 1 - epsilon (ties
--- drawn, see best), otherwise one of the others, uniformly. `uniform()` returns a number in [0, 1].
--- Returns an index and how it was picked ("greedy" or "epsilon"), or nil for an empty list.
function M.choose(list, epsilon, uniform)
  local n = #list
  if n == 0 then return nil end
  local best = M.best(list, uniform)
  if n == 1 then return best, "greedy" end
  if uniform() >= epsilon then return best, "greedy" end
  local k = math.floor(uniform() * (n - 1)) + 1   -- 1 .. n-1
  if k > n - 1 then k = n - 1 end
  if k >= best then k = k + 1 end                  -- skip the best one
  return k, "epsilon"
end

return M
