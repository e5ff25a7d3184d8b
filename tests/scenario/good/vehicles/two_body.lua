-- A small test vehicle file (not physical data): a frame and a wheelset on a spring.
return function(opts)
  opts = opts or {}
  local elements = {}
  for i, side in ipairs({ 1, -1 }) do
    elements[#elements + 1] = spring_damper {
      name = "primary_" .. i, from = "frame", to = "ws", at_from = { 0, side, 0 }, at_to = { 0, side, 0 },
      direction = "z", stiffness = 1.22e6, damping = 4e3,
    }
  end
  elements[#elements + 1] = series_damper {
    name = "series", from = "frame", to = "ws", direction = "z", damping = 4e3, series_stiffness = 1e6,
  }
  elements[#elements + 1] = bumpstop {
    name = "stop", from = "frame", to = "ws", direction = "y", table = { { 0.025, 0 }, { 0.03, 600 } },
  }
  return {
    name = "two_body", speed = opts.speed or 10,
    bodies = {
      body { name = "frame", kind = "frame", mass = 1, inertia = { 1, 1, 1 } },
      body { name = "ws", kind = "wheelset", mass = 1813, inertia = { 1120, 112, 1120 }, height = 0.46 },
    },
    elements = elements,
  }
end
