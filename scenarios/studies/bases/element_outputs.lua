-- Base of scenarios/studies/effects.lua:
-- case 3 writing the deflection and force of all 50 elements.
require "studies.wagon" { element_outputs = true }
