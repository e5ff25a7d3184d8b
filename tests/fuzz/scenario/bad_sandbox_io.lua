local f = io.open("/etc/passwd")
track { segments = { tangent { length = 30 } } }
