-- hostile: args="study {case} --out st"
-- hostile: expect="study_initial_rate.lua:7: vehicle.initial.ws1: yaw_dot must be <= 5 rad/s, got 1e+06"
-- hostile: reject="solver.step"
-- hostile: expect="nothing was run"
-- A yaw rate of 1e6 rad/s was blamed on solver.step (the stiff start's step check).
study { base = "base.lua", cases = {
    { ["vehicle.initial.ws1.yaw_dot"] = 1e6 },
  } }
