-- hostile: expect="rail_support_malformed.lua:11: contact.elastic.rail_support: unknown key 'stiffness'"
-- hostile: expect="contact.elastic.rail_support.along[2]: the points' s must increase strictly"
-- hostile: expect="contact.elastic.rail_support.along[3]: k_z must be >= 100000 N/m, got 1000"
-- hostile: expect="rail_support: along[4] must be { s = <m>, mass = .., k_z = .., ... }"
-- hostile: expect="contact.elastic.rail_support: every point needs mass, k_z and k_y"
-- The track under the rail, malformed: an unknown key, points out of order, a stiffness out of
-- range, an entry without s, and a support without its lateral stiffness.
track { segments = { tangent { length = 100 } } }
vehicle { speed = 10, bodies = { { name = "ws1", kind = "wheelset", mass = 1000, inertia = { 500, 100, 500 } } } }
contact { method = "elastic", elastic = { rail_support = {
  mass = 150, k_z = 1e8, stiffness = 3,
  along = { { s = 10 }, { s = 5 }, { s = 20, k_z = 1e3 }, { 5 } } } } }
