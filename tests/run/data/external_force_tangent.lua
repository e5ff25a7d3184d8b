-- The Manchester wagon 1 (scenarios/vehicles/manchester_wagon1.lua) at 20 m/s on a tangent
-- without irregularities, S1002 on 60E1 at 1:40, KEC contact, pushed to the left by an external
-- force on its car body (tests/run/test_external_force.cpp): 0 until t = 0.5 s, then rising at
-- 5 kN/s to 10 kN, which it keeps (a ramp of 2 s, slow against the car's 0.5 Hz lower sway, which
-- a faster one leaves swinging for seconds). In the steady state the rails carry the push: the wheels'
-- lateral forces add up to -10 kN, and each of the four secondary shear springs (160 kN/m) carries
-- a quarter of it. The push acts at the secondary spring height (0.9725 m below the car body's
-- centre of mass), where it hardly rolls the car. --set changes the force or the contact method.
local c = require "validation.common"
track { segments = { tangent { length = 300 } }, step = 0.5 }
c.profiles()
c.contact("kec")
local v = require "vehicles.manchester_wagon1" { speed = 20, start = 20 }
v.elements[#v.elements + 1] = external_force {
  name = "push", body = "car", at = { 0, 0, -0.9725 }, direction = { 0, 1, 0 },
  law = "ramp", start = 0.5, rate = 5e3, value = 10e3 }
vehicle (v)
c.abm(20, 1.25e-3)
run { output = { every = 0.01,
                 elements = { "sec_shear_y_bogie1_l", "sec_shear_y_bogie1_r",
                              "sec_shear_y_bogie2_l", "sec_shear_y_bogie2_r" } },
      duration = 8 }
