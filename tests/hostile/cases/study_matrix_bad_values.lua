-- hostile: args="study {case} --out st"
-- hostile: expect="study_matrix_bad_values.lua:9: vehicle: speed must be >= 0 m/s, got -5"
-- hostile: expect="study_matrix_bad_values.lua:9: vehicle: speed must be finite"
-- hostile: expect="study_matrix_bad_values.lua:9: vehicle: speed must be a number [m/s], got string \"heavy\""
-- hostile: expect="study_matrix_bad_values.lua:10: vehicle.bodies[1] (body): mass must be > 0 kg, got -1"
-- hostile: expect="nothing was run"
-- Bad matrix values ran every case and failed each at run time (exit 2, or 0 with one good case).
study { base = "base.lua", matrix = {
    ["vehicle.speed"] = { 10, -5, 0/0, "heavy" },
    ["vehicle.bodies.car.mass"] = { 30000, -1 },
  } }
