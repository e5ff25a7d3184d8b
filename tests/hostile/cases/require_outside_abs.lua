-- hostile: expect="module names are names separated by dots"
-- hostile: reject="SECRET"
-- The outside folder by absolute dotted path.
require("." .. ("{outside}"):gsub("/", "."):sub(2) .. ".secret")
