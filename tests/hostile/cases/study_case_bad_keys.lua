-- hostile: args="study {case} --out st"
-- hostile: expect="study_case_bad_keys.lua:9: run.assessment: alpha must be in (0, 1] or -1, got 5"
-- hostile: expect="study_case_bad_keys.lua:10: vehicle.elements[2] (spring_damper): unknown key 'nosuchkey'"
-- hostile: expect="study_case_bad_keys.lua:11: vehicle: initial: no body named 'nosuch'"
-- hostile: expect="nothing was run"
-- Case entries whose keys name nothing or whose values are out of range were accepted and failed
-- each run; now each is reported at its own line before anything runs.
study { base = "base.lua", cases = {
    { ["run.assessment.alpha"] = 5 },
    { ["vehicle.elements.prim_x_ws1_l.nosuchkey"] = 3 },
    { ["vehicle.initial.nosuch.y"] = 0.001 },
  } }
