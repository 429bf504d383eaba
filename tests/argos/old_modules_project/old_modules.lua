-- Counts its steps; the loop functions read the count from this state.
steps = 0

function step()
  steps = steps + 1
end
