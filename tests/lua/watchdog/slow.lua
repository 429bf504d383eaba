-- Slow in two ways (watchdog_test.py, with --lua-seconds): an endless Lua loop, or one
-- string.find that backtracks for hours inside C.
function step()
  if robot.params.mode == "find" then
    string.find(string.rep("a", 60), ".-.-.-.-.-.-.-.-.-.-.-.-b")
  else
    while true do end
  end
end
