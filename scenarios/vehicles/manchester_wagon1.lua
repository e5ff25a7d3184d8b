-- Manchester benchmark vehicle 1 (Iwnicki 1998) as used by the founding paper (Yu et al.,
-- section 5.1): 1 car body, 2 bogie frames, 4 wheelsets, the 48 suspension elements of Table 4
-- and the two anti-roll bars of the benchmark data [MB] (50 elements).
-- Usage:  local wagon = require "vehicles.manchester_wagon1"
--         vehicle (wagon { speed = 20 })
-- Options (defaults: the full model): speed [m/s] = 20, start [m] = 0, acceleration [m/s^2]
--   (vehicle.acceleration, default 0),
--   bumpstops = false        leaves out the two lateral bump stops (2 elements fewer)
--   anti_roll_bar = false    leaves out the two anti-roll bars: the paper's Table 4 alone (48
--                            elements with the bump stops)
--   series_dampers = false   the 16 series dampers (primary and secondary vertical, secondary
--                            lateral) become plain dampers: vertical Kz in parallel with Dz (no
--                            series stiffness), lateral Dsy alone (no series stiffness Ksy); 16
--                            fewer states (the damper forces)
--   primary_longitudinal_stiffness [N/m] = 31391e3 ([T4] Kpx): the primary longitudinal
--                            springs, which give the wheelset its yaw stiffness to the bogie
--                            (2 Kpx b^2 with b = 1 m); stability studies vary it
-- (scenarios/studies/effects.lua measures what each of these costs.)
-- Sources: [T2] paper Table 2 (masses, inertias); [T4] paper Table 4 (suspension);
-- [MB] Manchester benchmark vehicle 1 (Iwnicki, Vehicle System Dynamics 30, 1998), geometry as
-- recovered from a public parameter file of it (Source A of the project's reference notes);
-- ASSUMPTION marks values that are not published. docs/vehicle.md explains the element count.
--
-- Coordinates: body x is the CoM position along the track relative to the vehicle reference point
-- (car centre), positive forward; height is the CoM height above the top of rail. Attachment
-- points {x, y, z} are in the body frame (relative to its CoM; for wheelsets the non-spinning axle
-- box frame), y positive to the left. Every element goes from the upper body (master, "from") to
-- the lower one ("to"), so a positive vertical deflection is compression.
return function(opts)
  opts = opts or {}
  -- An option this file does not take would be dropped silently (a misspelt speed, a prescribed
  -- acceleration): refused at the line that gives it (level 2: the caller's).
  local known = { speed = true, start = true, acceleration = true, bumpstops = true, anti_roll_bar = true, series_dampers = true, primary_longitudinal_stiffness = true }
  for k in pairs(opts) do
    if not known[k] then
      error("vehicles.manchester_wagon1: unknown option '" .. tostring(k) .. "' (options: "
            .. "speed, start, acceleration, bumpstops, anti_roll_bar, series_dampers, primary_longitudinal_stiffness)", 2)
    end
  end
  local with_bumpstops = opts.bumpstops ~= false
  local with_series = opts.series_dampers ~= false
  local with_anti_roll = opts.anti_roll_bar ~= false
  local kpx = opts.primary_longitudinal_stiffness or 31391e3  -- [T4] Kpx [N/m]
  -- A series damper, or with series_dampers = false the plain damper (and parallel spring).
  local function damper(e)
    if with_series then return series_damper(e) end
    return spring_damper { name = e.name, from = e.from, to = e.to, at_from = e.at_from,
                           at_to = e.at_to, direction = e.direction, stiffness = e.stiffness or 0,
                           damping = e.damping }
  end

  local h_car   = 1.8     -- [MB] car body CoG height above rail
  local h_bogie = 0.6     -- [MB] bogie frame CoG height
  local r0      = 0.46    -- [MB] nominal wheel radius = axle (primary suspension) height
  local h_sec   = 0.8275  -- [MB] secondary suspension height
  local h_bump  = 0.65    -- [MB] lateral bump-stop height
  local a_bogie = 9.5     -- [MB] semi bogie-pivot spacing (bogie centres 19 m apart)
  local a_axle  = 1.28    -- [MB] bogie semi-wheelbase (wheelbase 2.56 m)
  local b_prim  = 1.0     -- [MB] primary suspension lateral semi-spacing
  local b_sec   = 1.0     -- [MB] secondary suspension lateral semi-spacing

  -- Bump stop force-deflection table [T4] (also [MB]): clearance 25 mm, then a stiffening curve.
  local bump_table = {
    { 0.000, 0 }, { 0.025, 0 }, { 0.030, 600 }, { 0.035, 1760 }, { 0.040, 3730 },
    { 0.045, 6870 }, { 0.050, 11580 }, { 0.055, 17170 }, { 0.060, 29200 }, { 0.065, 230000 },
  }

  local bodies = {
    -- [T2] car: 32000 kg, Ixx 56800, Iyy 1.97e6, Izz 1.97e6 kg m^2
    body { name = "car", kind = "car", mass = 32000, inertia = { 56800, 1970000, 1970000 },
           x = 0, height = h_car },
  }
  local elements = {}
  local function add(e) elements[#elements + 1] = e end

  for b, xb in ipairs({ a_bogie, -a_bogie }) do
    local bogie = "bogie" .. b
    -- [T2] bogie frame: 2615 kg, Ixx 1722, Iyy 1476, Izz 3067 kg m^2
    bodies[#bodies + 1] = body { name = bogie, kind = "bogie", mass = 2615,
                                 inertia = { 1722, 1476, 3067 }, x = xb, height = h_bogie }
    for a, xa in ipairs({ a_axle, -a_axle }) do
      local ws = "ws" .. (2 * (b - 1) + a)
      -- [T2] wheelset: 1813 kg, Ixx 1120, Iyy 112 (spin axis), Izz 1120 kg m^2
      bodies[#bodies + 1] = body { name = ws, kind = "wheelset", mass = 1813,
                                   inertia = { 1120, 112, 1120 }, x = xb + xa, height = r0 }
      for _, side in ipairs({ { "l", 1 }, { "r", -1 } }) do
        local tag, sy = side[1], side[2]
        local at_bogie = { xa, sy * b_prim, r0 - h_bogie }
        local at_ws = { 0, sy * b_prim, 0 }
        -- Primary vertical: Kpz 1220 kN/m in parallel with the damper Dpz 4 kN s/m that has the
        -- series stiffness Kseries_pz 1000 kN/m [T4], 4/bogie. ([MB] Source B has 1200 kN/m; the
        -- paper's 1220 is used.) One Table-4 element: a series_damper with a parallel stiffness.
        add(damper { name = "prim_z_" .. ws .. "_" .. tag, from = bogie, to = ws,
                            at_from = at_bogie, at_to = at_ws, direction = "z",
                            stiffness = 1220e3, damping = 4e3, series_stiffness = 1000e3 })
        -- Primary longitudinal: Kpx 31391 kN/m, Dpx 15 kN s/m in parallel [T4], 4/bogie.
        add(spring_damper { name = "prim_x_" .. ws .. "_" .. tag, from = bogie, to = ws,
                            at_from = at_bogie, at_to = at_ws, direction = "x",
                            stiffness = kpx, damping = 15e3 })
        -- Primary lateral: Kpy 3884 kN/m, Dpy 2 kN s/m in parallel [T4], 4/bogie.
        add(spring_damper { name = "prim_y_" .. ws .. "_" .. tag, from = bogie, to = ws,
                            at_from = at_bogie, at_to = at_ws, direction = "y",
                            stiffness = 3884e3, damping = 2e3 })
      end
    end

    local function at_car(y, h) return { xb, y, h - h_car } end
    local function at_bg(y, h) return { 0, y, h - h_bogie } end
    for _, side in ipairs({ { "l", 1 }, { "r", -1 } }) do
      local tag, sy = side[1], side[2]
      local pc, pb = at_car(sy * b_sec, h_sec), at_bg(sy * b_sec, h_sec)
      -- Secondary vertical: Ksz 430 kN/m in parallel with the damper Dsz 4 kN s/m that has the
      -- series stiffness Kseries_sz 1000 kN/m [T4], 2/bogie, at the secondary springs [MB].
      add(damper { name = "sec_z_" .. bogie .. "_" .. tag, from = "car", to = bogie,
                          at_from = pc, at_to = pb, direction = "z",
                          stiffness = 430e3, damping = 4e3, series_stiffness = 1000e3 })
      -- Secondary longitudinal and lateral shear stiffness of the springs: 160 kN/m each [T4],
      -- 2/bogie.
      add(shear_spring { name = "sec_shear_x_" .. bogie .. "_" .. tag, from = "car", to = bogie,
                         at_from = pc, at_to = pb, direction = "x", stiffness = 160e3 })
      add(shear_spring { name = "sec_shear_y_" .. bogie .. "_" .. tag, from = "car", to = bogie,
                         at_from = pc, at_to = pb, direction = "y", stiffness = 160e3 })
      -- Secondary bending stiffness Kbend 10.5 kN m/rad [T4], 2/bogie. ASSUMPTION: about the
      -- vertical axis (anti-yaw; [MB] calls K2b "secondary anti-bending/yaw stiffness").
      add(bending_spring { name = "sec_bend_" .. bogie .. "_" .. tag, from = "car", to = bogie,
                           at_from = pc, at_to = pb, direction = "z", stiffness = 10.5e3 })
      -- Secondary lateral: Dsy 32 kN s/m with Ksy 6000 kN/m [T4], 2/bogie, placed at the secondary
      -- springs (ASSUMPTION). ASSUMPTION: Ksy is the SERIES stiffness of the lateral damper (like
      -- Kseries of the vertical dampers), not a spring in parallel: read in parallel, the car sits
      -- 66 mm inside its track frame in the paper's R = 500 m curve at 20 m/s; as a series
      -- stiffness 28-31 mm (both measured without the anti-roll bars, which move the car towards
      -- the paper's value); the paper's Table 6 has 41.8 mm (KEC) / 41.4 mm (UM). See
      -- docs/vehicle.md, section 4, and the generated case-2 table of docs/validation.md.
      add(damper { name = "sec_y_" .. bogie .. "_" .. tag, from = "car", to = bogie,
                          at_from = pc, at_to = pb, direction = "y",
                          damping = 32e3, series_stiffness = 6000e3 })
    end
    -- Secondary longitudinal (traction link): Ksx 5000 kN/m, Dsx 25 kN s/m in parallel [T4],
    -- 1/bogie. ASSUMPTION: on the bogie centre line at the secondary suspension height.
    add(spring_damper { name = "sec_x_" .. bogie, from = "car", to = bogie,
                        at_from = at_car(0, h_sec), at_to = at_bg(0, h_sec), direction = "x",
                        stiffness = 5000e3, damping = 25e3 })
    -- Anti-roll bar: roll stiffness Kr 940 kN m/rad between car and bogie [MB] (the paper's
    -- Table 4 does not list it). ASSUMPTION: 1/bogie (the reference file gives one value and no
    -- count; a torsion bar per bogie is the usual arrangement), a bending spring about the
    -- longitudinal axis (relative roll of car and bogie) at the secondary suspension height on the
    -- bogie centre (its position does not enter a bending spring's moment).
    if with_anti_roll then
      add(bending_spring { name = "anti_roll_" .. bogie, from = "car", to = bogie,
                           at_from = at_car(0, h_sec), at_to = at_bg(0, h_sec), direction = "x",
                           stiffness = 940e3 })
    end
    -- Lateral bump stop, table above [T4]; ASSUMPTION: 1/bogie on the bogie centre line, at the
    -- bump-stop height 0.65 m [MB].
    if with_bumpstops then
      add(bumpstop { name = "bump_y_" .. bogie, from = "car", to = bogie,
                     at_from = at_car(0, h_bump), at_to = at_bg(0, h_bump), direction = "y",
                     table = bump_table })
    end
  end

  -- Named groups of elements for sweeps: --set vehicle.groups.GROUP.KEY=VALUE sets KEY in every
  -- member (`workbench help vehicle SCENARIO.lua` lists them with the keys all members have).
  -- They only name elements: the model is the same with or without them.
  local groups = {
    -- The 8 primary longitudinal springs Kpx: the wheelsets' yaw stiffness to the bogie
    -- (2 Kpx b^2, b = 1 m); keys stiffness, damping.
    primary_longitudinal = { "prim_x_*" },
    primary_lateral = { "prim_y_*" },        -- Kpy, Dpy: stiffness, damping
    -- Kpz with its damper Dpz: stiffness, damping, series_stiffness (the latter not with
    -- series_dampers = false).
    primary_vertical = { "prim_z_*" },
    secondary_vertical = { "sec_z_*" },      -- Ksz, Dsz, Kseries_sz
    secondary_lateral = { "sec_y_*" },       -- lateral dampers Dsy: damping, series_stiffness
    secondary_longitudinal = { "sec_x_*" },  -- traction links Ksx, Dsx
    secondary_shear = { "sec_shear_*" },     -- shear stiffness of the springs, x and y
    secondary_bending = { "sec_bend_*" },    -- Kbend
  }
  if with_anti_roll then groups.anti_roll = { "anti_roll_*" } end
  if with_bumpstops then groups.bumpstops = { "bump_y_*" } end
  -- The mirrored left/right pairs, which a symmetric vehicle varies together: per wheelset
  -- (prim_x_ws1 = prim_x_ws1_l and prim_x_ws1_r, ...) and per bogie (sec_z_bogie1, ...).
  for w = 1, 4 do
    for _, d in ipairs({ "x", "y", "z" }) do
      local pair = "prim_" .. d .. "_ws" .. w
      groups[pair] = { pair .. "_l", pair .. "_r" }
    end
  end
  for b = 1, 2 do
    for _, e in ipairs({ "sec_z", "sec_y", "sec_shear_x", "sec_shear_y", "sec_bend" }) do
      local pair = e .. "_bogie" .. b
      groups[pair] = { pair .. "_l", pair .. "_r" }
    end
  end

  return {
    name = "manchester_wagon1",
    speed = opts.speed or 20,  -- [m/s] paper case 2/3: V = 20 m/s
    wheel_radius = r0,
    -- EN 14363 category (alpha = 1.0 of the track shift limit). ASSUMPTION: the benchmark's
    -- vehicle 1 is a passenger coach (a 32 t body on two bogies 19 m apart with two-stage
    -- suspension, as Iwnicki 1998 describes it; the paper itself was not at hand).
    category = "passenger",
    start = opts.start or 0,
    acceleration = opts.acceleration,  -- nil: the engine's default 0 (no speed ramp)
    bodies = bodies,
    elements = elements,
    groups = groups,
  }
end
