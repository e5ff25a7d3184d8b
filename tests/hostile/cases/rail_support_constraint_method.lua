-- hostile: expect="rail_support_constraint_method.lua:5: contact: elastic applies to method = \"elastic\" only"
-- The track under the rail asked of a constraint contact method (the KEC has no rail to move).
track { segments = { tangent { length = 100 } } }
vehicle { speed = 10, bodies = { { name = "ws1", kind = "wheelset", mass = 1000, inertia = { 500, 100, 500 } } } }
contact { method = "kec", elastic = { rail_support = { mass = 150, k_z = 1e8, k_y = 4e7 } } }
