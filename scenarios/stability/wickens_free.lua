-- Free wheelset (no lateral or yaw spring) of the Wickens case (tests/wickens/README.md): the
-- kinematic (Klingel) oscillation. Otherwise as wickens.lua: the wheelset of
-- wickens_wheelset.lua on a tangent without irregularities, S1002 on 60E1, Kalker's linear creep
-- (the closed form's creep law). The tests change the inclination and the contact method with
-- --set (profiles.inclination, contact.method) and the speed on the compiled model.
track { segments = { tangent { length = 20000 } }, step = 0.5 }
-- S1002 on 60E1, B = 1360 mm, G = 1435 mm, r0 = 0.46 m, as the paper's validation cases
-- (scenarios/validation/common.lua), but inclined 1:60: at the project's usual 1:40 the centred
-- contact lies 0.23 mm from a contact-point jump (docs/contact_geometry.md, section 7), which the
-- KEC regularises over dhat + dbar = 1.5 mm, so its centred contact is split over two patches
-- (Eq. 26) and the single-contact closed form does not describe it. At 1:60 both KEC and LUT
-- have one smooth contact per wheel at y = 0.
profiles { wheel = "s1002", rail = "60e1", back_to_back = 1.360, gauge = 1.435, r0 = 0.46,
           inclination = 1 / 60 }
-- KEC with the paper's transition lengths (section 2.4), Kalker linear theory (Kalker 1990,
-- Table E.3) with E = 210 GPa, nu = 0.28 (paper section 5.3); consistent normal forces (a
-- finite-difference Jacobian needs a memory-free rhs).
contact { method = "kec", creep = "kalker", normal_forces = "consistent" }
vehicle (require "stability.wickens_wheelset" { speed = 10, ky = 0, kx = 0 })
solver { method = "dopri5" }
run { duration = 1, output = { every = 0.01 } }
