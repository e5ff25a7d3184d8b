-- hostile: args="study {case} --out st"
-- hostile: expect="study_double_dot.lua:6: study: \"solver..step\": 'solver..step' is not a key path"
-- hostile: expect="nothing was run"
-- "solver..step" was read as "solver.step".
study { base = "base.lua", cases = {
    { ["solver..step"] = 1e-3 },
  } }
