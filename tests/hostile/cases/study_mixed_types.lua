-- hostile: args="study {case} --out st"
-- hostile: expect="study_mixed_types.lua:8: vehicle.elements"
-- hostile: expect="got string \"stiff\""
-- hostile: expect="nothing was run"
-- Mixed types in one matrix axis: the number runs, the string and the boolean were each a run
-- failure.
study { base = "base.lua", matrix = {
    ["vehicle.groups.primary_longitudinal.stiffness"] = { 1e6, "stiff", true },
  } }
