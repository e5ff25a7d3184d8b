-- sliced_rails_common.lua with the left rail alone lowered by 3 mm over the 40 m from s = 60 m to
-- 100 m: a cross level of 3 mm reached over 40 m.
local ramp = { { s = 60, rail = "rails/60e1_a.txt" }, { s = 100, rail = "rails/60e1_low3.txt" } }
require "sliced_rails_common" ({ left = ramp }, 5.5)
