-- Base of scenarios/studies/effects.lua:
-- case 3 with plain dampers instead of the 16 series dampers.
require "studies.wagon" { series_dampers = false }
