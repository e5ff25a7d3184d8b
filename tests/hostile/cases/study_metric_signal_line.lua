-- hostile: args="study {case} --out st"
-- hostile: expect="study_metric_signal_line.lua:9: study.metrics[2] (typo): signal '/bodies/ws9/y': no body 'ws9'"
-- hostile: expect="nothing was run"
-- A metric reading a signal no case writes: at the metric's own line (it was the study's line),
-- before any run.
study { base = "base.lua",
  metrics = {
    { name = "fine", signal = "/bodies/ws1/y", stat = "max_abs" },
    { name = "typo", signal = "/bodies/ws9/y", stat = "max" },
  } }
