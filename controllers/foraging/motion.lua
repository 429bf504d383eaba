-- Wheel-speed laws of chapter 4 (pure functions; speeds in cm/s, angles in rad, 0 = ahead,
-- positive = to the left, as the foot-bot's sensors report them).
local M = {}

local pi = math.pi

--- Convergence law (report 4.2): wheel speeds that turn the robot towards a direction `theta`
--- while the mean speed stays `speed`. The wheel on the goal's side runs at
--- ((pi - |theta|) / pi)^kappa * speed, the other one at 2 * speed minus that:
--- theta = 0 gives (speed, speed); a goal on the left (theta > 0) makes the right wheel faster;
--- convergence(-theta) is convergence(theta) with the wheels swapped.
--- Returns left, right.
function M.convergence(theta, speed, kappa)
  if theta > pi then theta = pi elseif theta < -pi then theta = -pi end
  local inner = ((pi - math.abs(theta)) / pi) ^ kappa * speed
  local outer = 2 * speed - inner
  if theta >= 0 then
    return inner, outer
  else
    return outer, inner
  end
end

--- Position of a direction on one side of the robot, on the scale of the foot-bot proximity ring:
--- 1 for the frontmost sensor (7.5 deg) to 12 for the rearmost one (172.5 deg). Continuous, so
--- scanner directions map onto it too: s = 0.5 + 12 |theta| / pi.
function M.side_index(theta)
  return 0.5 + 12 * math.abs(theta) / pi
end

--- Avoidance law (report 4.4; 4.5 with other constants): obstacle in direction `theta`, closeness
--- `prox` in [0, 1] (1 = touching). With s = side_index(theta), the wheel away from the obstacle
--- runs at ((1 - prox)^beta * s - alpha) / 11 * speed and the other at 2 * speed minus that, so the
--- robot turns away, harder when the obstacle is close and in front; an obstacle behind and far
--- leaves the robot going straight. alpha: direction dependence, beta: proximity dependence.
--- theta >= 0 (obstacle on the left, ring sensors 1..12) slows the right wheel.
--- Returns left, right.
function M.avoidance(theta, prox, speed, alpha, beta)
  if prox < 0 then prox = 0 elseif prox > 1 then prox = 1 end
  local s = M.side_index(theta)
  local near = ((1 - prox) ^ beta * s - alpha) * speed / 11
  local far = 2 * speed - near
  if theta >= 0 then
    return far, near
  else
    return near, far
  end
end

--- Angle (rad) of foot-bot proximity sensor i (1..24): 7.5 deg + 15 deg * (i - 1), wrapped.
function M.proximity_angle(i)
  local a = pi / 24 + (i - 1) * pi / 12
  if a > pi then a = a - 2 * pi end
  return a
end

--- Strongest reading of the proximity ring. `readings` is robot.proximity (array of
--- {value, angle}). Ties go to the most frontal sensor (listing 4.9). Returns value, angle;
--- value 0 means nothing within the ring's 10 cm.
function M.strongest(readings)
  local best, best_angle = 0, 0
  for i = 1, #readings do
    local r = readings[i]
    local v = r.value
    local a = r.angle or M.proximity_angle(i)
    if v > best or (v == best and v > 0 and math.abs(a) < math.abs(best_angle)) then
      best, best_angle = v, a
    end
  end
  return best, best_angle
end

--- Closeness in [0, 1] of a short-range obstacle at `distance` cm, for the intermediate avoidance:
--- 1 at contact, 0 at `reach` cm and beyond.
function M.closeness(distance, reach)
  local p = 1 - distance / reach
  if p < 0 then return 0 elseif p > 1 then return 1 end
  return p
end

-- Random slower speed after a hit (annex 4.B) ------------------------------------------------------

--- New speed state: { speed = base, last_hit = nil }.
function M.new_speed_state(base)
  return { speed = base, last_hit = nil }
end

--- Updates the speed state at step `tick`. On a hit, a new speed
--- uniform(min_coeff, 1) * base is drawn unless the previous random speed is still running
--- (a hit within `duration` steps of the last one keeps it); every hit restarts the clock. Without
--- a hit, the base speed comes back once `duration` steps have passed since the last hit.
--- `uniform(a, b)` is the random source (robot.random.uniform). Returns the speed.
function M.update_speed(state, hit, tick, base, min_coeff, duration, uniform)
  local running = state.last_hit ~= nil and tick - state.last_hit <= duration
  if hit then
    if not running then
      state.speed = uniform(min_coeff, 1) * base
    end
    state.last_hit = tick
  elseif not running then
    state.speed = base
  end
  return state.speed
end

return M
