-- hostile: expect="elastic_refined_tables.lua:5: profiles.refined_tables has no effect with contact.method = \"elastic\""
-- Refined contact tables asked for with the elastic method, which has no tables: refused at the
-- key's line instead of silently unused.
track { segments = { tangent { length = 100 } } }
profiles { refined_tables = true }
contact { method = "elastic", creep = "polach" }
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
