-- hostile: args="study {case} --out st"
-- hostile: expect="study_metric_lines.lua:8:"
-- hostile: expect="nothing was run"
-- Metric declarations with problems are reported at each metric's own line, not the study's.
study { base = "base.lua",
  metrics = {
    { name = "fine", signal = "/bodies/ws1/y", stat = "max_abs" },
    { name = "badstat", signal = "/bodies/ws1/y", stat = "maximum" },
    { name = "fine2", signal = "/bodies/ws1/y", stat = "rms" },
  } }
