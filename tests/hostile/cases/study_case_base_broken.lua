-- hostile: args="study {case} --out st"
-- hostile: expect="study_case_base_broken.lua:8: in the scenario of the case: broken.lua:3: run: duration must be >= 0 s, got -1"
-- hostile: expect="nothing was run"
-- A case's own base scenario that does not load: the problem at the case's entry, naming the
-- base scenario's own line; the good case does not run either.
study { base = "base.lua", cases = {
    { label = "good" },
    { label = "bad", base = "broken.lua" },
  } }
