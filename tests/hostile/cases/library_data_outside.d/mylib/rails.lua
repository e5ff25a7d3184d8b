local M = {}
M.measured = measured { file = "secret.csv" }
M.wheel = "../../../../../../../../../etc/passwd"
return M
