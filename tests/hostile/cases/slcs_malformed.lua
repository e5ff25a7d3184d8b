-- hostile: expect="slcs_malformed.lua:12: profiles: rail_slices.left: unknown key 'scale'"
-- hostile: expect="rail_slices.right.units must be \"mm\" or \"m\", got string \"cm\""
-- hostile: expect="extra_rails.right[1].slices.s must be the track arc length [m] of the slices-file's u = 0"
-- hostile: expect="extra_rails.left[1].slices.slcs: "
-- hostile: expect="bad.slcs:3: NSLC must be a whole number in [1, 2000], got 2.5"
-- A CONTACT slices-file given badly: an unknown key, a unit that is not one, no s, and a
-- slices-file that is malformed (at its own line).
track { segments = { tangent { length = 100 } } }
contact { method = "elastic" }
vehicle (require "vehicles.manchester_wagon1" { speed = 20, start = 20 })
profiles {
  rail_slices = { left = { slcs = "bad.slcs", s = 10, scale = 1000 },
                  right = { slcs = "bad.slcs", s = 10, units = "cm" } },
  extra_rails = { right = { { name = "nose", slices = { slcs = "bad.slcs" } } },
                  left = { { name = "nose", slices = { slcs = "bad.slcs", s = 10 } } } } }
