-- Battery management (report 6.2.2, annex 6.D), pure functions. Battery in units (0..100).
local M = {}

--- Battery the robot estimates it needs to fly home: mu * batt_per_step * distance / speed
--- (distance in cm, speed in cm/s; mu absorbs the steps-per-second factor and the detours).
function M.needed(mu, batt_per_step, distance, speed)
  return mu * batt_per_step * distance / speed
end

--- True when the robot must head home: what is left after the estimated return falls below the
--- leftover it should keep (IDEAL_NEST_BATT).
function M.must_go_home(battery, mu, batt_per_step, distance, speed, ideal)
  return battery - M.needed(mu, batt_per_step, distance, speed) < ideal
end

--- New safety coefficient after a return home with `leftover` units left (listing 6.13): a
--- surplus above `ideal` lowers mu by gain_down per unit, a deficit raises it by gain_up per unit.
--- mu never drops below `floor` (the report has no floor; judged at every return, as the
--- behaviour does, the surpluses of trips to a near source would drive mu to zero, and the robot
--- would then head for a far source with no margin at all).
function M.update_safety(mu, leftover, ideal, gain_down, gain_up, floor)
  local gap = leftover - ideal
  if gap > 0 then
    mu = mu - gap * gain_down
  else
    mu = mu - gap * gain_up
  end
  if floor and mu < floor then mu = floor end
  return mu
end

return M
