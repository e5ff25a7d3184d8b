-- Base of scenarios/studies/effects.lua: case 3 without the two lateral bump stops.
require "studies.wagon" { bumpstops = false }
