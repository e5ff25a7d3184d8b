-- hostile: args="study {case} --run-timeout -1 --jobs 0 --out st"
-- hostile: expect="--run-timeout -1: must be a finite time >= 0 s (0: no limit)"
-- hostile: expect="--jobs 0: must be in 1.."
-- hostile: expect="2 problems found; nothing was run."
-- hostile: timeout=20
-- Both options at once, each with its value.
study {
  base = "base.lua",
  cases = { { ["run.duration"] = 0.1 } },
  repeats = 1,
}
