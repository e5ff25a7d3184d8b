-- Base of scenarios/studies/effects.lua:
-- case 3 without irregularities, bump stops and series dampers.
require "studies.wagon" { irregularities = false, bumpstops = false, series_dampers = false }
