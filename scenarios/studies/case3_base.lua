-- Base scenario of the studies: the paper's case 3 (Manchester wagon, R = 500 m, V = 20 m/s, ORE
-- B176 low irregularities, seed 42) with a contact block that either method accepts, so a study
-- can switch contact.method, contact.flange_stiffness and the solver by --set.
require("validation.common").wagon("study", true)
