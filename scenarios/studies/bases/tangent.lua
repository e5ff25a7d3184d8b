-- Base of scenarios/studies/effects.lua:
-- a 500 m tangent with the case-3 irregularities: no curving, no flange contact.
require "studies.wagon" { tangent = true }
