-- Single wheelset held by lateral and yaw springs to a kinematic frame on tangent track: the
-- classical verification case of wheelset hunting (Wickens, "The dynamic stability of railway
-- vehicle wheelsets and bogies having profiled wheels", Int. J. Solids Struct. 1, 1965; Wickens,
-- Fundamentals of Rail Vehicle Dynamics, 2003, chapter 2). The frame (kind = "frame") follows the
-- track centreline at constant speed directly over the wheelset (as frame = "centred" in
-- vehicles/single_wheelset.lua) and holds it by
--   two lateral springs ky/2 at the axle boxes (lateral stiffness ky),
--   two longitudinal springs kx at +-b (yaw stiffness kpsi = 2 kx b^2),
--   no damping (the closed form has none),
--   a constant vertical load per axle box (a zero-stiffness element with a preload), so the
--   vertical suspension adds no stiffness to the lateral/yaw motion of the constrained wheelset
--   (its height and roll follow from the contact constraints).
-- Options (SI): speed [m/s] = 30, ky [N/m] = 2e6, kx [N/m] = 0.4e6, b [m] = 1.0, load [N] (vertical
--   load on the wheelset, both axle boxes together) = the single_wheelset.lua value.
-- Usage:  vehicle (require "stability.wickens_wheelset" { speed = 40, ky = 2e6, kx = 0.4e6 })
-- Sources: [T2] Yu et al. Table 2 (Manchester wheelset); [MB] Manchester benchmark vehicle 1
-- (Iwnicki, Vehicle System Dynamics 30, 1998).
return function(opts)
  opts = opts or {}
  local r0 = 0.46      -- [MB] nominal wheel radius
  local h_frame = 0.6  -- [MB] bogie frame CoG height (the frame stands in for the bogie)
  -- [MB] primary lateral semi-spacing 1.0 m; ASSUMPTION: the springs sit at the axle boxes.
  local b = opts.b or 1.0
  -- ASSUMPTION: spring values chosen, not data: soft enough that the closed-form critical speed
  -- lies in 20-200 m/s for S1002/60E1 at rail inclinations 1:20 to 1:60 (tests/wickens/README.md),
  -- and the lateral spring dominates the restoring terms (then the critical speed scales with
  -- 1/sqrt(conicity) most closely). The Manchester primary suspension ([T4]: Kpy 3884 kN/m, Kpx
  -- 31391 kN/m) would put it far above 200 m/s.
  local ky = opts.ky or 2e6
  local kx = opts.kx or 0.4e6
  local g = 9.81
  -- Quarter of the sprung weight of the Manchester wagon, (car 32000 kg [T2] + 2 bogies x
  -- 2615 kg [T2]) / 4 * g = 91 307 N, as in vehicles/single_wheelset.lua (ASSUMPTION there).
  local load = opts.load or (32000 + 2 * 2615) / 4 * g

  local elements = {}
  local function add(e) elements[#elements + 1] = e end
  for _, side in ipairs({ { "l", 1 }, { "r", -1 } }) do
    local tag, sy = side[1], side[2]
    local at_frame = { 0, sy * b, r0 - h_frame }
    local at_ws = { 0, sy * b, 0 }
    add(spring_damper { name = "yaw_x_" .. tag, from = "frame", to = "ws", at_from = at_frame,
                        at_to = at_ws, direction = "x", stiffness = kx, damping = 0 })
    add(spring_damper { name = "lat_y_" .. tag, from = "frame", to = "ws", at_from = at_frame,
                        at_to = at_ws, direction = "y", stiffness = ky / 2, damping = 0 })
    add(spring_damper { name = "load_" .. tag, from = "frame", to = "ws", at_from = at_frame,
                        at_to = at_ws, direction = "z", stiffness = 0, damping = 0,
                        preload = load / 2 })
  end

  return {
    name = "wickens_wheelset",
    speed = opts.speed or 30,
    wheel_radius = r0,
    bodies = {
      -- The frame's mass plays no role (its motion is prescribed); 1 kg satisfies the schema.
      body { name = "frame", kind = "frame", mass = 1, inertia = { 1, 1, 1 }, x = 0,
             height = h_frame },
      -- [T2] wheelset: 1813 kg, Ixx 1120, Iyy 112, Izz 1120 kg m^2
      body { name = "ws", kind = "wheelset", mass = 1813, inertia = { 1120, 112, 1120 }, x = 0,
             height = r0 },
    },
    elements = elements,
  }
end
