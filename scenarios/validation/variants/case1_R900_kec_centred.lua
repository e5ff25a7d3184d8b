-- Paper section 5.2, case 1 (KEC), R = 900 m, variant: the wheelset's frame on the centreline at the
-- wheelset itself (no bogie-frame yaw against the curve), beside the shipped set-up of
-- ../case1_R900_kec.lua (the guided frame of a bogie whose leading wheelset it is).
-- docs/validation.md compares both with the paper's Table 5.
require("validation.common").case1(900, "kec", "centred")
