-- hostile: expect="study_in_scenario.lua:4: study{} belongs in a study file"
-- A study block inside a scenario was ignored.
track { segments = { tangent { length = 100 } } }
study { base = "x.lua" }
