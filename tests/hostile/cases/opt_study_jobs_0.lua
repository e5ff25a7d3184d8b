-- hostile: args="study {case} --jobs 0 --out st"
-- hostile: expect="--jobs 0: must be in 1.."
-- hostile: expect="nothing was run"
-- hostile: timeout=20
-- A typed --jobs outside 1..4 x cores was taken (0 as "the default", 100000 as is).
study {
  base = "base.lua",
  cases = { { ["run.duration"] = 0.1 } },
  repeats = 1,
}
