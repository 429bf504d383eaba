// The mistakes of an `essaim test` spec, all found at once (docs/testing.md): expectations
// the grammar refuses, an experiment or workdir that is not there (with "did you mean" among
// the .argos files near the spec) before any run; after the runs, a value that no run produced.
// Each is "FILE:LINE: message".
#pragma once
#include <string>
#include <vector>

#include "app/expectation.h"
#include "app/test_spec.h"

namespace essaim {

/// Parses every expectation of `spec` and checks its paths; appends one error per mistake.
void CheckSpec(const TestSpec& spec, std::vector<Expectation>* expectations, std::vector<std::string>* errors);
/// After the runs: "FILE:LINE: ..." when no finished run produced the expectation's value.
std::string UnknownValueInSpec(const TestSpec& spec, const Expectation& e, const std::vector<SeedOutcome>& runs);

}  // namespace essaim
