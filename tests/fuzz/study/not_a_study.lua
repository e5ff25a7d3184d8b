-- No study block; blocks of a scenario instead.
run { distance = 1 }
solver { method = "rk4", step = 1e-3 }
