require ".etc.passwd"
