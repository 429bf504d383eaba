-- Loop functions whose post_step never returns (watchdog_test.py): the run ends, exit 1.
function post_step()
  if experiment.tick == 3 then
    while true do end
  end
end
