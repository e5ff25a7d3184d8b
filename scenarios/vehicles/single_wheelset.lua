-- Single wheelset of the paper's case 1 (Yu et al., section 5.2: V = 10 m/s on the
-- wheelset_validation_R* tracks). The paper does not say how the wheelset is loaded or held.
-- ASSUMPTION (docs/vehicle.md, section 5): the wheelset is the leading wheelset of a bogie whose
-- frame is guided along the track: a kinematic frame (kind = "frame") follows the track
-- centreline at constant speed, its centre the bogie semi-wheelbase 1.28 m behind the wheelset,
-- and holds the wheelset through the primary suspension of one axle of the Manchester wagon ([T4]
-- paper Table 4) at the axle-box positions of the wagon. The wheelset carries a quarter of the
-- wagon's sprung weight, applied as a constant vertical load on each axle box. Why this set-up:
-- the paper's only vehicle data are the Manchester wagon's (Tables 2 and 4), whose primary
-- suspension joins each wheelset to a bogie frame centred 1.28 m from it; and its Table 5 puts
-- the single wheelset at -8.83 mm on R = 500 m, where its Table 6 puts the wagon's leading
-- wheelsets (-8.83 mm): the single wheelset behaves as a leading wheelset, in flange contact.
-- Options: speed [m/s] = 10, start [m] = 0 (the frame centre's start position; the wheelset is
--   1.28 m ahead of it), acceleration [m/s^2] (vehicle.acceleration, default 0),
--   frame = "bogie" (default, above) | "centred": the frame on the centreline at the wheelset
--           itself (a wheelset in the middle of a bogie, held by the primary suspension without
--           the frame's yaw against the curve), kept as a variant:
--           scenarios/validation/variants/.
-- Usage:  local ws = require "vehicles.single_wheelset"
--         vehicle (ws { speed = 10 })
-- Sources: [T2] paper Table 2; [T4] paper Table 4; [MB] Manchester benchmark vehicle 1 (Iwnicki,
-- Vehicle System Dynamics 30, 1998).
return function(opts)
  opts = opts or {}
  -- An option this file does not take would be dropped silently (a misspelt speed, a prescribed
  -- acceleration): refused at the line that gives it (level 2: the caller's).
  local known = { speed = true, start = true, acceleration = true, frame = true }
  for k in pairs(opts) do
    if not known[k] then
      error("vehicles.single_wheelset: unknown option '" .. tostring(k) .. "' (options: "
            .. "speed, start, acceleration, frame)", 2)
    end
  end
  local frame = opts.frame or "bogie"
  assert(frame == "bogie" or frame == "centred",
         "single_wheelset: frame must be \"bogie\" or \"centred\", got " .. tostring(frame))
  -- [MB] bogie semi-wheelbase: the wheelset's position ahead of the frame centre
  local a_axle = frame == "bogie" and 1.28 or 0
  local r0 = 0.46       -- [MB] nominal wheel radius
  local h_frame = 0.6   -- [MB] bogie frame CoG height (the frame stands in for the bogie)
  local b_prim = 1.0    -- [MB] primary lateral semi-spacing
  local g = 9.81
  -- Quarter of the sprung weight of the wagon: (car 32000 kg [T2] + 2 bogies x 2615 kg [T2]) / 4,
  -- i.e. the static load of one wheelset's primary suspension. ASSUMPTION (see header).
  local load = (32000 + 2 * 2615) / 4 * g   -- [N] per wheelset, 91 307 N

  local elements = {}
  local function add(e) elements[#elements + 1] = e end
  for _, side in ipairs({ { "l", 1 }, { "r", -1 } }) do
    local tag, sy = side[1], side[2]
    local at_frame = { a_axle, sy * b_prim, r0 - h_frame }
    local at_ws = { 0, sy * b_prim, 0 }
    -- Primary vertical [T4]: Kpz 1220 kN/m in parallel with Dpz 4 kN s/m / Kseries 1000 kN/m.
    add(series_damper { name = "prim_z_" .. tag, from = "frame", to = "ws", at_from = at_frame,
                        at_to = at_ws, direction = "z", stiffness = 1220e3, damping = 4e3,
                        series_stiffness = 1000e3 })
    -- Primary longitudinal [T4]: Kpx 31391 kN/m, Dpx 15 kN s/m.
    add(spring_damper { name = "prim_x_" .. tag, from = "frame", to = "ws", at_from = at_frame,
                        at_to = at_ws, direction = "x", stiffness = 31391e3, damping = 15e3 })
    -- Primary lateral [T4]: Kpy 3884 kN/m, Dpy 2 kN s/m.
    add(spring_damper { name = "prim_y_" .. tag, from = "frame", to = "ws", at_from = at_frame,
                        at_to = at_ws, direction = "y", stiffness = 3884e3, damping = 2e3 })
    -- Axle box load: half the wheelset load per side, a constant force pushing the axle box down
    -- (a zero-stiffness element with a preload; positive = compression from frame to wheelset).
    add(spring_damper { name = "load_" .. tag, from = "frame", to = "ws", at_from = at_frame,
                        at_to = at_ws, direction = "z", stiffness = 0, damping = 0,
                        preload = load / 2 })
  end

  return {
    name = "single_wheelset",
    speed = opts.speed or 10,  -- [m/s] paper case 1: V = 10 m/s
    wheel_radius = r0,
    start = opts.start or 0,
    acceleration = opts.acceleration,  -- nil: the engine's default 0 (no speed ramp)
    bodies = {
      -- The frame's mass plays no role (its motion is prescribed); 1 kg satisfies the schema.
      body { name = "frame", kind = "frame", mass = 1, inertia = { 1, 1, 1 }, x = 0,
             height = h_frame },
      -- [T2] wheelset: 1813 kg, Ixx 1120, Iyy 112, Izz 1120 kg m^2
      body { name = "ws", kind = "wheelset", mass = 1813, inertia = { 1120, 112, 1120 },
             x = a_axle, height = r0 },
    },
    elements = elements,
  }
end
