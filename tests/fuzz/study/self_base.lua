-- The study file is its own case's base, and a base outside the folder.
study {
  base = "study.lua",
  cases = { { base = "./study.lua", ["run.distance"] = 1 },
            { base = "../../etc/passwd", ["run.distance"] = 2 } },
}
