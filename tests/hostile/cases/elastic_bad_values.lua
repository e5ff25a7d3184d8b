-- hostile: expect="elastic_bad_values.lua:7: contact.elastic: unknown key 'damping' (valid keys: damping_ratio" expect="elastic_bad_values.lua:7: contact.elastic: sample_step must be >= 2e-05 m" expect="elastic_bad_values.lua:8: contact.elastic: derailment_lift must be in" expect="elastic_bad_values.lua:8: contact.elastic: min_curvature_ratio must be >= 0.01"
-- The elastic method's block with a misspelt key, a scan step that would make every search take
-- seconds (1 nm), a derailment lift of 0.2 mm (below any wheel's bounce) and a curvature floor
-- of 0: every problem refused where it is written, nothing is run.
track { segments = { tangent { length = 100 } } }
contact { method = "elastic", creep = "polach",
  elastic = { damping = 0.1, sample_step = 1e-9,
              derailment_lift = 0.2e-3, min_curvature_ratio = 0 } }
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
