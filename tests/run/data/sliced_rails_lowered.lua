-- sliced_rails_common.lua with both rails lowered by 3 mm over the 40 m from s = 60 m to 100 m
-- (rails/60e1_low3.txt is rails/60e1_a.txt with z - 3 mm): a ramp of 1:13333.
local ramp = { { s = 60, rail = "rails/60e1_a.txt" }, { s = 100, rail = "rails/60e1_low3.txt" } }
require "sliced_rails_common" ({ left = ramp, right = ramp }, 5.5)
