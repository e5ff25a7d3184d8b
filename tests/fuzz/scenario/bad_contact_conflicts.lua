track { segments = { tangent { length = 100 } }, rail_lr = 0.7555 }
profiles { wheel = "s1002", rail = "missing.prr", lr = 0.7555, gauge = 1.435 }
contact { method = "kec", flange_stiffness = 1e10 }
