-- hostile: expect="rail_support_not_a_list.lua:7: contact.elastic.rail_support: along must be a list of 1 to 2000 points"
-- The track under the rail whose `along` is not a list of points.
track { segments = { tangent { length = 100 } } }
vehicle { speed = 10, bodies = { { name = "ws1", kind = "wheelset", mass = 1000, inertia = { 500, 100, 500 } } } }
contact { method = "elastic", elastic = { rail_support = {
  mass = 150, k_z = 1e8, k_y = 4e7,
  along = "soft" } } }
