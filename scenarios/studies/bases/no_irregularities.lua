-- Base of scenarios/studies/effects.lua: case 3 without track irregularities (the paper's case 2).
require "studies.wagon" { irregularities = false }
