-- A small test vehicle file (not physical data): a frame and a wheelset, two mirrored springs,
-- a series damper and a bump stop, with groups; opts.groups adds or replaces groups.
return function(opts)
  opts = opts or {}
  local groups = {
    pair = { "spring_l", "spring_r" },
    springs = { "spring_*" },
    all = { "*" },
  }
  for k, v in pairs(opts.groups or {}) do groups[k] = v end
  return {
    name = "tiny", speed = 10,
    bodies = {
      body { name = "frame", kind = "frame", mass = 1, inertia = { 1, 1, 1 } },
      body { name = "ws", kind = "wheelset", mass = 1813, inertia = { 1120, 112, 1120 }, height = 0.46 },
    },
    elements = {
      spring_damper { name = "spring_l", from = "frame", to = "ws", at_from = { 0, 1, 0 },
                      at_to = { 0, 1, 0 }, direction = "z", stiffness = 1e6, damping = 4e3 },
      spring_damper { name = "spring_r", from = "frame", to = "ws", at_from = { 0, -1, 0 },
                      at_to = { 0, -1, 0 }, direction = "z", stiffness = 1e6, damping = 4e3 },
      series_damper { name = "damper", from = "frame", to = "ws", direction = "z", damping = 4e3,
                      series_stiffness = 1e6 },
      bumpstop { name = "stop", from = "frame", to = "ws", direction = "y",
                 table = { { 0.025, 0 }, { 0.03, 600 } } },
      spring_damper { name = "dotted.name", from = "frame", to = "ws", direction = "x",
                      stiffness = 5e5 },
    },
    groups = groups,
  }
end
