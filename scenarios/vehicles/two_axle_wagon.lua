-- A two-axle freight wagon: one car body on two wheelsets, linear primary suspension.
-- ASSUMPTION: a generic design (not a published vehicle) with values typical of a loaded
-- two-axle wagon on UIC double-link suspension, linearised: the links' pendulum stiffness as
-- lateral and longitudinal springs, little damping (the friction of the links is not modelled).
-- Such wagons show the low-speed car-body instability of the stability literature (the car body
-- yaw/sway driven by the kinematic motion of the wheelsets when its frequency comes near the body
-- mode's, Wickens, "Fundamentals of rail vehicle dynamics", 2003, ch. 6), well below their
-- wheelset hunting speed: the stability commands must report it (docs/stability.md).
-- Usage:  vehicle ((require "vehicles.two_axle_wagon") { speed = 10 })
-- Options: speed [m/s] = 10, start [m] = 0, acceleration [m/s^2] (vehicle.acceleration,
-- default 0).
return function(opts)
  opts = opts or {}
  -- An option this file does not take would be dropped silently (a misspelt speed, a prescribed
  -- acceleration): refused at the line that gives it (level 2: the caller's).
  local known = { speed = true, start = true, acceleration = true }
  for k in pairs(opts) do
    if not known[k] then
      error("vehicles.two_axle_wagon: unknown option '" .. tostring(k) .. "' (options: "
            .. "speed, start, acceleration)", 2)
    end
  end
  local h_car = 1.5    -- [m] car body CoM height above rail
  local r0 = 0.46      -- [m] nominal wheel radius (axle height)
  local a_axle = 4.5   -- [m] semi-wheelbase (wheelbase 9 m)
  local b_prim = 1.0   -- [m] lateral semi-spacing of the primary suspension
  local bodies = {
    body { name = "car", kind = "car", mass = 20000, inertia = { 30000, 200000, 200000 },
           x = 0, height = h_car },
  }
  local elements = {}
  for a, xa in ipairs({ a_axle, -a_axle }) do
    local ws = "ws" .. a
    bodies[#bodies + 1] = body { name = ws, kind = "wheelset", mass = 1400,
                                 inertia = { 800, 100, 800 }, x = xa, height = r0 }
    for _, side in ipairs({ { "l", 1 }, { "r", -1 } }) do
      local tag, sy = side[1], side[2]
      local at_car = { xa, sy * b_prim, r0 - h_car }
      local at_ws = { 0, sy * b_prim, 0 }
      elements[#elements + 1] = spring_damper {
        name = "prim_z_" .. ws .. "_" .. tag, from = "car", to = ws, at_from = at_car,
        at_to = at_ws, direction = "z", stiffness = 1.2e6, damping = 10e3 }
      elements[#elements + 1] = spring_damper {
        name = "prim_x_" .. ws .. "_" .. tag, from = "car", to = ws, at_from = at_car,
        at_to = at_ws, direction = "x", stiffness = 0.8e6, damping = 1e3 }
      elements[#elements + 1] = spring_damper {
        name = "prim_y_" .. ws .. "_" .. tag, from = "car", to = ws, at_from = at_car,
        at_to = at_ws, direction = "y", stiffness = 0.4e6, damping = 1e3 }
    end
  end
  return {
    name = "two_axle_wagon",
    speed = opts.speed or 10,
    wheel_radius = r0,
    start = opts.start or 0,
    acceleration = opts.acceleration,  -- nil: the engine's default 0 (no speed ramp)
    bodies = bodies,
    elements = elements,
    groups = { primary_longitudinal = { "prim_x_*" }, primary_lateral = { "prim_y_*" },
               primary_vertical = { "prim_z_*" } },
  }
end
