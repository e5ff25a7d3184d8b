track { segments = { tangent { length = 100 } } }
profiles { wheel = "s1002", rail = "../../../profiles/MBench_UIC60_v3.prr", lw = 0.7515, lr = 0.7555, r0 = 0.457 }
contact { method = "lut", flange_stiffness = 7.075e13, mu = 0.3 }
