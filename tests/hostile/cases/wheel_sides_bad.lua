-- hostile: expect="wheel_sides_bad.lua:8: profiles: wheel_right: file"
-- hostile: expect="not found"
-- hostile: expect="wheel_sides_bad.lua:8: profiles: wheel_left must be a string"
-- Each wheel's own profile: a missing file, and a value that is not a name.
track { segments = { tangent { length = 100 } } }
contact { method = "kec" }
vehicle { speed = 10, bodies = { { name = "ws1", kind = "wheelset", mass = 1000, inertia = { 500, 100, 500 } } } }
profiles { wheel = "s1002", wheel_left = 3, wheel_right = "missing_right.txt" }
