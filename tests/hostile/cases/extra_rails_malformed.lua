-- hostile: expect="extra_rails_malformed.lua:16: profiles: extra_rails.right[1].name 'rail' is taken"
-- hostile: expect="extra_rails.right[2] must be { name = \"nose\""
-- hostile: expect="extra_rails.right[3].slices[1].dz must be an offset of at most 0.5 m, got number 7"
-- hostile: expect="extra_rails.right[3].slices[2] must be { s = <m>, rail ="
-- hostile: expect="extra_rails.left[2].name 'blade' is taken"
-- Further rails, malformed: the running rail's name, a name with a space, an offset of metres, an
-- unknown slice key, a name given twice.
track { segments = { tangent { length = 100 } } }
contact { method = "elastic" }
vehicle { speed = 10, bodies = { { name = "ws1", kind = "wheelset", mass = 1000, inertia = { 500, 100, 500 } } } }
local one = { { s = 10, rail = "60e1" } }
local r = { { name = "rail", slices = one }, { name = "check rail", slices = one },
            { name = "nose", slices = { { s = 1, rail = "60e1", dz = 7 }, { s = 2, rail = "60e1", dx = 1 } } } }
local l = { { name = "blade", slices = one }, { name = "blade", slices = one } }
profiles {
  extra_rails = { left = l, right = r } }
