-- Counts the robots in the zones of data/zones.txt every tick into zone_counts.txt: both
-- paths relative to the working directory, as an ARGoS project's loop functions write them.
local helper = dofile("zones_helper.lua")
local zones, out = {}, nil

function init()
  for line in io.lines("data/zones.txt") do
    local x, y, radius = line:match("^(%S+)%s+(%S+)%s+(%S+)$")
    if x then zones[#zones + 1] = {x = tonumber(x), y = tonumber(y), radius = tonumber(radius)} end
  end
  out = assert(io.open("zone_counts.txt", "w"))
  out:write("tick inside zones seed\n")
end

function post_step()
  local inside = 0
  for _, r in ipairs(experiment.robots) do
    local x, y = r:position()
    for _, zone in ipairs(zones) do
      if helper.inside(zone, x, y) then inside = inside + 1 break end
    end
  end
  out:write(string.format("%d %d %d %d\n", experiment.tick, inside, #zones, experiment.seed))
end

function post_experiment()
  out:close()
end
