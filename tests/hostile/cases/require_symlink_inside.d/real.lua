return { tangent { length = 100 } }
