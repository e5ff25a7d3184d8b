-- hostile: expect="derailment_lift_negative.lua:7: contact.elastic: derailment_lift must be in [0.001, 0.1] m or -1, got -0.5"
-- derailment_lift takes [0.001, 0.1] m or the sentinel -1 (half the flange height); -0.5 lay
-- inside the schema's old range [-1, 0.1] and was accepted.
track { segments = { tangent { length = 100 } } }
contact { method = "elastic", creep = "polach",
  elastic = {
    derailment_lift = -0.5 } }
vehicle (require "vehicles.single_wheelset" { speed = 10 })
solver { method = "abm", step = 2e-4 }
