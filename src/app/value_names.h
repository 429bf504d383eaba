// The names an `essaim test` expectation can read in a run (docs/testing.md): metrics.json's
// numbers by dotted key, summary.KEY, errors, ticks. Used to tell a misspelled name (no run
// produced it: a mistake of the spec, with "did you mean") from a value that only some runs
// lack (a per-seed failure, with why).
#pragma once
#include <string>
#include <vector>

#include "app/expectation.h"

namespace essaim {

/// Why `name` (one side of a ratio, not a file column) has no number in `run`; "" when it has.
std::string WhyNoValue(const SeedOutcome& run, const std::string& name);
/// For a VALUE (A/B included) that none of `runs` produced: the message naming it, with the
/// closest name they did produce. "" when some run has it, or when `runs` is empty.
std::string UnknownValueError(const std::string& value, const std::vector<SeedOutcome>& runs);

}  // namespace essaim
