-- hostile: expect="extra_rails_too_many.lua:7: profiles: extra_rails.left must be a list of 1 to 3 rails"
-- Four further rails on a side: more than a turnout has (blade, nose, check rail).
track { segments = { tangent { length = 100 } } }
contact { method = "elastic" }
vehicle { speed = 10, bodies = { { name = "ws1", kind = "wheelset", mass = 1000, inertia = { 500, 100, 500 } } } }
local function rail(n) return { name = n, slices = { { s = 10, rail = "60e1" } } } end
profiles { extra_rails = { left = { rail("a"), rail("b"), rail("c"), rail("d") } } }
