-- sliced_rails_common.lua with the left rail 3 mm lower than profiles.rail from the start: the
-- wheelsets start on it, rolled by the cross level (tests/run/test_sliced_rails.cpp).
local low = { { s = 0, rail = "rails/60e1_low3.txt" }, { s = 300, rail = "rails/60e1_low3.txt" } }
require "sliced_rails_common" ({ left = low }, 0.2)
