-- Wickens single-wheelset stability case (tests/wickens/README.md): the wheelset of
-- wickens_wheelset.lua on a tangent without irregularities, S1002 on 60E1, Kalker's linear creep
-- (the closed form's creep law). The tests change speed, springs, inclination and contact method
-- with --set (vehicle.speed, profiles.inclination, contact.method).
track { segments = { tangent { length = 20000 } }, step = 0.5 }
-- S1002 on 60E1 at 1:40, B = 1360 mm, G = 1435 mm, r0 = 0.46 m: the profiles of the paper's
-- validation cases (scenarios/validation/common.lua).
profiles { wheel = "s1002", rail = "60e1", back_to_back = 1.360, gauge = 1.435, r0 = 0.46,
           inclination = 0.025 }
-- KEC with the paper's transition lengths (section 2.4), Kalker linear theory (Kalker 1990,
-- Table E.3) with E = 210 GPa, nu = 0.28 (paper section 5.3); consistent normal forces (a
-- finite-difference Jacobian needs a memory-free rhs).
contact { method = "kec", creep = "kalker", normal_forces = "consistent" }
vehicle (require "stability.wickens_wheelset" { speed = 30 })
solver { method = "dopri5" }
run { duration = 1, output = { every = 0.01 } }
