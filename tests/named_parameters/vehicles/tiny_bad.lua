-- A test vehicle file whose groups name nothing: the errors are reported at these lines.
-- (this comment, typo = { "sprung_r" }, is not the line of the group typo)
return function()
  return {
    name = "tiny_bad", speed = 10,
    bodies = {
      body { name = "frame", kind = "frame", mass = 1, inertia = { 1, 1, 1 } },
      body { name = "ws", kind = "wheelset", mass = 1813, inertia = { 1120, 112, 1120 }, height = 0.46 },
    },
    elements = {
      spring_damper { name = "spring_l", from = "frame", to = "ws", direction = "z", stiffness = 1e6 },
      spring_damper { name = "spring_r", from = "frame", to = "ws", direction = "z", stiffness = 1e6 },
    },
    groups = {
      good = { "spring_*" },
      typo = { "spring_l", "sprung_r" },
      nothing = { "damper_*" },
      empty = {},
    },
  }
end
