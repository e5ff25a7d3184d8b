-- hostile: expect="method_unknown_once.lua:5: contact: method: unknown value 'KEC' (did you mean 'kec'?)" expect="1 problem found"
-- An unknown contact method is one problem, said once (the guided check and the method's own
-- reading both reported it).
track { segments = { tangent { length = 100 } } }
contact { method = "KEC" }
vehicle (require "vehicles.single_wheelset" { speed = 10 })
