-- Shared set-up of the hard-case stability suite (issue 7 item 4; docs/hard_cases.md):
--   local hard = require "hard.lib"
-- Profiles, friction and the paper's contact constants come from scenarios/validation/common.lua
-- (S1002 on 60E1 at 1:40, B = 1360 mm, G = 1435 mm, r0 = 0.46 m, mu = 0.2364: paper Table 1 and
-- section 5.1, with the 60E1 substitution explained there).
local common = require "validation.common"
local M = {}

M.profiles = common.profiles

-- Paper Table 3 / section 5.3: Hertz flange stiffness of S1002 on the paper's rail from Hertz
-- theory with E = 2.1e11 Pa, nu = 0.28, and D = K/100.
M.K_HERTZ = 7.075e13   -- [N/m^1.5] paper section 5.3, Table 3 first column
M.D_HERTZ = 7.075e11   -- [N s/m^2] paper Table 3 first column (= K/100)
M.MU_PAPER = 0.2364    -- paper section 5.1

-- A left curve of radius R reached over a short tangent and clothoid, no cant.
-- ASSUMPTION: no cant, so the whole lateral acceleration V^2/R is cant deficiency; short
-- approach (tangent, transition) so that the flange is reached within a few simulated seconds.
function M.curve_track(R, opts)
  opts = opts or {}
  local irr = nil
  if opts.irregularities then
    -- ORE B176 spectra (paper section 5.2 uses "low"; "high" is the rougher ORE class), seed 42
    -- as in case 3; band 3..70 m and 0.1 m step as in the paper (Fig. 15).
    -- fade_in = 0: the irregularities start at s = 0 as in the paper, so the flange impacts this
    -- suite and its expected outcomes (tests/hard/expect) were made for stay where they are.
    irr = psd { spectrum = opts.irregularities, seed = opts.seed or 42, wavelengths = { 3, 70 },
                step = 0.1, fade_in = 0 }
  end
  track {
    segments = {
      tangent    { length = opts.tangent or 10 },
      transition { length = opts.transition or 20, radius = R, side = "left" },
      curve      { length = opts.curve or 300, radius = R, side = "left" },
    },
    step = 0.5,                      -- paper: 0.5 m
    irregularities = irr,
  }
end

return M
