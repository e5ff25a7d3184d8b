-- hostile: expect="wheelsets_malformed.lua:9: profiles: wheelsets.ws1: unknown key 'wheel_rite' (did you mean 'wheel_right'?)"
-- hostile: expect="wheelsets.ws2.wheel must be \"s1002\" or a wheel profile file, got number 3"
-- hostile: expect="wheelsets.ws3 must be { wheel = ..., wheel_left = ..., wheel_right = ... } (at least one), got string"
-- hostile: expect="wheelsets.ws4.wheel_left: "
-- hostile: expect="(did you mean the built-in profile 's1002'?)"
-- Wheelsets with wheels of their own, malformed: an unknown key, a number for a profile, an entry
-- that is not a table, and a profile that is neither the built-in one nor a file.
track { segments = { tangent { length = 100 } } }
profiles { wheelsets = { ws1 = { wheel_rite = "s1002" }, ws2 = { wheel = 3 }, ws3 = "s1002",
                         ws4 = { wheel_left = "S1002" } } }
contact { method = "elastic" }
vehicle (body { name = "ws1", kind = "wheelset", mass = 1000, inertia = { 500, 100, 500 } })
