local make = require "vehicles.two_body"
local function at(start)
  local v = make { speed = 12 }
  v.start = start
  return v
end
track { segments = { tangent { length = 100 } } }
contact { method = "guided" }
train { vehicles = {
  { name = "front", vehicle = at(40) },
  { name = "rear", vehicle = at(20), contact = { method = "guided" } },
} }
solver { method = "abm", step = 1e-3 }
