-- hostile: args="stress {case} --axes friction --values friction=5 --quick"
-- hostile: expect="axis friction value 5 (--values friction=...; contact.mu=5): "
-- hostile: expect="mu must be <= 1"
-- hostile: timeout=20
-- The refusal names the axis value the user typed, not only contact.mu.
require("validation.common").wagon("study", true)
