-- sliced_rails_common.lua with both rails 3 mm lower than profiles.rail from the start
-- (rails/60e1_low3.txt everywhere): the wheelsets start on the slices, not in the air above them
-- (tests/run/test_sliced_rails.cpp).
local low = { { s = 0, rail = "rails/60e1_low3.txt" }, { s = 300, rail = "rails/60e1_low3.txt" } }
require "sliced_rails_common" ({ left = low, right = low }, 0.2)
