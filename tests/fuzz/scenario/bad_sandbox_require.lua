local x = require "../../../etc/passwd"
