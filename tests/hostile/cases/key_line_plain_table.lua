-- hostile: expect="key_line_plain_table.lua:10: run.assessment: alpha must be in (0, 1] or -1, got 5"
-- hostile: expect="key_line_plain_table.lua:12: run.assessment: sections[1]"
-- A key inside a plain table was reported at the line of the block (run {), not its own.
track { segments = { tangent { length = 100 } } }
vehicle(require "vehicles.manchester_wagon1" { speed = 20 })
contact { method = "kec" }
run {
  duration = 0.1,
  assessment = {
    alpha = 5,
    sections = {
      { name = "a", from = 50, to = 10 },
    },
  },
}
