// The runs of `essaim test`: one child process of this same binary per seed (`essaim run`),
// at most `jobs` at a time. A child that crashes, is killed or fails to load counts as a
// failed run of its seed; it never takes the test down.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "app/expectation.h"
#include "app/test_spec.h"

namespace essaim {

struct SeedRunsOptions {
  std::string out;  // runs go into OUT/seed-N/ (their output folder and run.log)
  int jobs = 1;
  /// The seed whose run is recorded (--record) for a golden comparison; none when unset.
  bool record_golden = false;
};

/// The folder of one seed's run.
std::string SeedRunFolder(const std::string& out, uint64_t seed);
/// The shell command that reruns one seed alone as the spec ran it (its workdir, experiment,
/// ticks, --set and run folder), without the test's --quiet and --threads 1.
std::string RerunCommand(const TestSpec& spec, uint64_t seed, const std::string& out);
/// Runs every seed of `spec`; one outcome per seed, in the spec's order.
std::vector<SeedOutcome> RunSeeds(const TestSpec& spec, const SeedRunsOptions& options);

}  // namespace essaim
