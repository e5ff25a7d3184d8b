while true do pcall(function() while trud do end end) end
