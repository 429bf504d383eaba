-- Floor reading (report annex 6.A.2), pure functions. Sources and nest are black discs on a white
-- floor; the base ground sensor gives 0 (black) or 1 (white) per sensor.
local M = {}

--- From the 8 base-ground values: `see` = some sensor is on black (touching a disc),
--- `inside` = every sensor is on black (the body is well inside a disc). Returns see, inside.
function M.read(values)
  local see, inside = false, #values > 0
  for i = 1, #values do
    local v = values[i]
    if type(v) == "table" then v = v.value end
    local black = v < 0.5
    see = see or black
    inside = inside and black
  end
  return see, inside
end

--- What the black under the robot is, from its distance to the nest centre (cm): "nest" when
--- within nest_radius + nest_margin, "source" beyond nest_radius + source_margin, nil otherwise
--- (ambiguous band) or when the robot sees no black.
function M.classify(see, distance_to_nest, nest_radius, nest_margin, source_margin)
  if not see then return nil end
  if distance_to_nest <= nest_radius + nest_margin then return "nest" end
  if distance_to_nest >= nest_radius + source_margin then return "source" end
  return nil
end

return M
