-- hostile: expect="b.lua:1: require \"a\": require cycle: a -> b -> a"
-- a requires b requires a.
require "a"
