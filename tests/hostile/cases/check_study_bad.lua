-- hostile: args="check {case}"
-- hostile: expect="check_study_bad.lua:6: vehicle: speed must be >= 0 m/s, got -5"
-- hostile: expect="nothing was run"
-- `workbench check` on a study file checks it as `workbench study` does before its first run
-- (it reported only that a scenario cannot hold a study block).
study { base = "base.lua", matrix = { ["vehicle.speed"] = { 10, -5 } } }
