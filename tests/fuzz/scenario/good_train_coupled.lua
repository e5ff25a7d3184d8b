local make = require "vehicles.two_body"
local function at(start)
  local v = make { speed = 12 }
  v.start = start
  return v
end
track { segments = { tangent { length = 200 } } }
contact { method = "guided" }
train {
  vehicles = {
    { name = "front", vehicle = at(60), traction = { { 0, 0 }, { 0.1, -2e3 } },
      resistance = { a = 100, b = 1, c = 0.1 } },
    { name = "rear", vehicle = at(40) },
  },
  connections = { { front = "front", rear = "rear", front_end = -5, rear_end = 5,
                    buffers = { loading = { { 0, 0 }, { 0.1, 1e5 } },
                                unloading = { { 0, 0 }, { 0.1, 4e4 } },
                                spacing = 1.75, height = 1.0, friction = 0.2 },
                    draw_gear = { stiffness = 1e6, slack = 0.01, height = 1.0 } } },
  longitudinal = { traction_at = "vehicle", min_speed = 1 },
}
solver { method = "abm", step = 1e-3 }
run { duration = 0.2 }
