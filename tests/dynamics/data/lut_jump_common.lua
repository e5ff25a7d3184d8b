-- A lone wheelset held in yaw only, for steady curving next to the S1002/60E1 tread/root
-- contact-point jump (issue 46 section 3; docs/contact_dynamics.md, "The LUT next to a
-- contact-point jump"): two longitudinal springs (x) at +-1 m to a kinematic frame on the
-- centreline at the wheelset, a constant vertical load of 100 kN on the axle (50 kN per axle box,
-- zero-stiffness elements), no lateral or vertical stiffness: the wheelset is free laterally and
-- cannot steer. In steady curving without cant the lateral forces of the two rails on it carry its
-- centripetal force m V^2 / R alone (the springs act along x; gravity and the load act along z).
-- At R = 300 m and 10 m/s it settles at y = -4.9 mm, next to the jump of the right (outer) wheel's
-- contact point from the tread to the flange root (|y| = 4.99 mm at xi_g = 0, docs/contact_geometry.md);
-- at R = 1000 m it settles on the tread away from any jump.
-- Usage: require "lut_jump_common" { radius = 300, method = "lut" }
local lib = require "tracks.lib"
return function(opts)
  local radius = opts.radius
  local method = opts.method or "lut"
  local speed = 10
  track { segments = {
            tangent    { length = 20 },
            transition { length = 30, radius = radius, side = "left" },
            curve      { length = 250, radius = radius, side = "left" },
          }, step = 0.5 }
  -- The validation cases' profiles (S1002 on 60E1 at 1:40) and contact blocks.
  require("validation.common").profiles()
  require("validation.common").contact(method)
  local els = {}
  for _, sd in ipairs({ { "l", 1 }, { "r", -1 } }) do
    local at_f, at_w = { 0, sd[2] * 1.0, 0.46 - 0.6 }, { 0, sd[2] * 1.0, 0 }
    -- Longitudinal primary stiffness of the Manchester wagon (paper Table 4): holds the yaw.
    els[#els + 1] = spring_damper { name = "px_" .. sd[1], from = "frame", to = "ws",
                                    at_from = at_f, at_to = at_w, direction = "x",
                                    stiffness = 31391e3, damping = 15e3 }
    els[#els + 1] = spring_damper { name = "load_" .. sd[1], from = "frame", to = "ws",
                                    at_from = at_f, at_to = at_w, direction = "z",
                                    stiffness = 0, damping = 0, preload = 50e3 }
  end
  vehicle { name = "yaw_held_wheelset", speed = speed, wheel_radius = 0.46,
    bodies = {
      body { name = "frame", kind = "frame", mass = 1, inertia = { 1, 1, 1 }, height = 0.6 },
      -- [T2] paper Table 2: the Manchester wheelset, 1813 kg.
      body { name = "ws", kind = "wheelset", mass = 1813, inertia = { 1120, 112, 1120 },
             height = 0.46 },
    },
    elements = els }
  require("validation.common").abm(speed)
  run { duration = 30, output = { every = 0.01 } }
end
