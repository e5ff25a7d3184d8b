-- A user PSD given as a Lua function and as a table; plain Lua arithmetic and loops.
local A, Oc, Or = 2.119e-7, 0.8246, 0.0206
local function ore(omega) return A * Oc^2 / ((omega^2 + Or^2) * (omega^2 + Oc^2)) end
local tbl = {}
for i = 0, 20 do
  local om = 0.05 * 1.3^i
  tbl[#tbl + 1] = { om, ore(om) }
end
track {
  segments = { tangent { length = 400 } },
  irregularities = psd {
    spectrum = "user",
    alignment = ore,
    vertical = tbl,
    channels = { "alignment", "vertical" },
    seed = 3,
  },
}
solver { method = "bdf", rtol = 1e-5, atol = 1e-7, max_step = 1e-3 }
run { distance = 300, output = { every = 0.005 } }
vehicle (require "vehicles.two_body" { speed = 10 })
-- Guided wheelsets, asked for by name (a vehicle with wheelsets needs a contact{} block).
contact { method = "guided" }
