-- hostile: args="stress {case} --axes friction --values friction=0.100,0.110,0.120,0.130,0.140,0.150,0.160,0.170,0.180,0.190,0.200,0.210,0.220,0.230,0.240,0.250,0.260,0.270,0.280,0.290,0.300,0.310,0.320,0.330,0.340,0.350,0.360,0.370,0.380,0.390"
-- hostile: expect="--values friction=...: more than 20 values of one axis"
-- hostile: timeout=20
-- Thousands of values were accepted and run (each a reference and every setting): bounded.
require("validation.common").wagon("study", true)
