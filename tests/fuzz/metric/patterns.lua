-- Pattern functions: affordable, beyond the bound, plain, through string metatables.
study {
  base = "base.lua",
  metrics = {
    { name = "ok", signals = { y = "/y" }, fn = function(s) return ("aaa"):find("a.") end },
    { name = "slow", signals = { y = "/y" },
      fn = function(s) return (("a"):rep(5000)):find("a*a*a*a*b") end },
    { name = "plain", signals = { y = "/y" },
      fn = function(s) return (("a"):rep(5000)):find("a*a*a*a*b", 1, true) or 0 end },
    { name = "gsub", signals = { y = "/y" }, fn = function(s)
        local r, n = string.gsub(("ab"):rep(100), "(a)(b)", "%2%1")
        return n
      end },
    { name = "gm", signals = { y = "/y" }, fn = function(s)
        local n = 0
        for w in ("a b c"):gmatch("%a") do n = n + 1 end
        return n
      end },
    { name = "bal", signals = { y = "/y" },
      fn = function(s) return #(("(((x)))"):rep(50):match("%b()") or "") end },
  },
}
