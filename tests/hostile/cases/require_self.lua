-- hostile: expect="require cycle: require_self -> require_self"
-- The scenario requires itself by name.
require "require_self"
