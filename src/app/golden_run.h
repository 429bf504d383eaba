// The golden run of `essaim test` (docs/testing.md): one seed's recording hash and metrics,
// stored in a JSON file beside the spec; a later run that differs fails with the differences,
// and --update rewrites the file, saying what changed.
#pragma once
#include <string>
#include <vector>

#include "app/expectation.h"

namespace essaim {

struct GoldenResult {
  bool pass = false;
  bool written = false;            // --update wrote the file
  std::string value;               // for the table: "same", "3 differences", "no golden file"...
  std::vector<std::string> diffs;  // "metrics.trips: 12 -> 14", "recording: fnv1a64:... -> ..."
};

/// Compares `run` (its folder holds recording.bin) with `golden_file`; with `update`, writes
/// the run's values there instead (and reports what changed against the old file).
GoldenResult CheckGolden(const std::string& golden_file, const SeedOutcome& run, const std::string& run_folder,
                         bool update);

}  // namespace essaim
