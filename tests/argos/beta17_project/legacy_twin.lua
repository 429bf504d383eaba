-- The same loop functions in Lua, written from essaim's own handles: the file they write
-- must hold the poses the ARGoS 3.0.0-beta17 loop functions read through their old names.
local out
local start = {}

local function write_rows()
  for _, r in ipairs(experiment.robots) do
    local x, y = r:position()
    local s = start[r.id]
    out:write(string.format("%d\t%s\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%.17g\n", experiment.tick, r.id, x, y,
      r:heading(), s[1], s[2], s[3]))
  end
  local light = experiment.entities("light")[1]
  local lx, ly = light:position()
  out:write(string.format("%d\tbeacon\t%.17g\t%.17g\n", experiment.tick, lx, ly))
end

function init()
  out = io.open(experiment.params.params.output, "w")
  for _, r in ipairs(experiment.robots) do
    local x, y = r:position()
    start[r.id] = { x, y, r:heading() }
  end
  experiment.robots[4]:set_pose(-1.0, 1.0, math.pi / 2)
  experiment.add_entity("cylinder", { id = "post", position = { 0, -1.6 }, radius = 0.1, height = 0.2 })
  experiment.entities("light")[1]:set_pose(1.5, 1.5)
  write_rows()
end

function post_step()
  write_rows()
end

function destroy()
  out:close()
end
