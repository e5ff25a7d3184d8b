-- hostile: expect="module names are names separated by dots"
-- Path separators.
require "../../../etc/passwd"
