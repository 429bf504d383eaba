-- Beside zones.argos: the loop functions load it with a relative dofile().
local helper = {}
function helper.inside(zone, x, y)
  return (x - zone.x) ^ 2 + (y - zone.y) ^ 2 <= zone.radius ^ 2
end
return helper
