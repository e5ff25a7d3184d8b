os.execute("touch /tmp/railbench_sandbox_escape")
track { segments = { tangent { length = 30 } } }
