-- Swarm foraging controller for the foot-bot, after the report "Robots en Essaim: Explorez"
-- (ULB, BA2 project, group 9): explore the arena with a gas-like walk, find black sources with the
-- ground sensor, share them over range-and-bearing, mine them with an epsilon-greedy choice, avoid
-- obstacles with the distance scanner and the proximity ring, and come home before the battery
-- runs out.
--
-- Devices: differential_steering, footbot_proximity, footbot_distance_scanner (sensor and
-- actuator), footbot_base_ground, range_and_bearing (sensor and actuator), positioning, battery,
-- leds. Parameters: every constant of foraging/config.lua, as <params> attributes.
--
-- LEDs: green = exploring, yellow = mining (going to a source), orange = mining (going back to
-- the nest), red = going home for the battery.
--
-- This file is only the glue between `robot` and the behaviour (foraging/behaviour.lua).
local config = require "foraging.config"
local behaviour = require "foraging.behaviour"
local sensing = require "foraging.sensing"

local cfg, state, tick, shown_color, shown_decisions

-- The last decision, for loop functions that watch them (arenas/foraging_loop.lua,
-- decisions="series" or "log"): decision_count counts them, decision is the last one,
-- {tick, why, x, y, battery, mu}: why as in behaviour.note_decision, x, y the source headed for (m;
-- nil when heading home). Written only when a decision is taken, so it costs nothing per step.
decision_count, decision = 0, nil

local function publish_decision()
  local target = state.target and state.sources[state.target]
  local heading = target and not state.going_home
  decision = { tick = tick, why = state.why, battery = state.battery_prev, mu = state.mu,
               x = heading and target.x / 100 or nil, y = heading and target.y / 100 or nil }
  decision_count = state.decisions
  shown_decisions = state.decisions
end

function init()
  cfg = config.load(robot.params)
  state = behaviour.new(cfg, robot.random)
  tick = 0
  shown_color = nil
  shown_decisions, decision_count, decision = 0, 0, nil
  if robot.distance_scanner then
    robot.distance_scanner.enable()
    robot.distance_scanner.set_rpm(cfg.SCANNER_RPM)
  end
  if robot.leds then
    shown_color = state.mode == "mine" and behaviour.COLORS.to_source or behaviour.COLORS.explore
    robot.leds.set_all_colors(shown_color)
  end
end

function step()
  tick = tick + 1
  local actions = behaviour.step(state, sensing.percepts(robot, tick))
  robot.wheels.set_velocity(actions.left, actions.right)
  if actions.message and robot.range_and_bearing then
    robot.range_and_bearing.set_data(actions.message)
  end
  if robot.leds and actions.color ~= shown_color then
    robot.leds.set_all_colors(actions.color)
    shown_color = actions.color
  end
  if state.decisions ~= shown_decisions then publish_decision() end
end

function reset()
  if robot.range_and_bearing then robot.range_and_bearing.clear_data() end
  init()
end

function destroy()
end
