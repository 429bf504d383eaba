// An expectation of `essaim test` (docs/testing.md), parsed from its text by a small fixed
// grammar (nothing is evaluated), and checked over the runs of every seed:
//   each VALUE OP N                 every run
//   mean|median|min|max VALUE OP N  over the runs
//   quantile(P) VALUE OP N          the P-quantile over the runs (P in [0, 1])
//   fraction(VALUE OP N) OP F       the fraction of runs meeting the inner condition
// VALUE: `errors` (controller errors plus a failed run), `ticks`, `summary.KEY` (summary.json),
// `metrics.KEY` or a bare KEY (metrics.json); a dotted KEY goes into nested objects; A/B (no
// spaces) is the ratio of two values, e.g. trips_per_source.A/trips_total; files/PATH[COL].STAT
// a column of a file the run wrote (app/file_column.h).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/value.h"

namespace essaim {

enum class Aggregate { Each, Mean, Median, Min, Max, Quantile, Fraction };

struct Comparison {
  std::string op;  // == != < <= > >=
  double threshold = 0;
  bool Holds(double v) const;
};

struct Expectation {
  std::string text;
  Aggregate aggregate = Aggregate::Each;
  double quantile = 0.5;  // Quantile only
  std::string value;      // the run value it reads
  Comparison per_run;     // Fraction only: what a run must meet to count
  Comparison check;       // on the aggregate (Each: on every run)
  int line = 0;           // in the spec, for messages
};

/// What one seed's run left: its exit, summary.json and metrics.json (null when absent).
struct SeedOutcome {
  uint64_t seed = 0;
  int exit_code = -1;   // -1: killed by a signal or never started
  std::string failure;  // why the run did not finish ("" when it exited 0)
  Value summary;
  Value metrics;
  std::string folder;  // the run folder (files/ below it)
  double seconds = 0;
};

struct Verdict {
  bool pass = false;
  std::string value;                   // what was measured, as shown in the table
  std::vector<uint64_t> failed_seeds;  // the runs whose own value fails it (or lacks it)
  std::vector<std::string> notes;      // why runs lack a file column: "seed 3: files/x.txt: ..."
};

/// False with a message naming the part that is wrong.
bool ParseExpectation(const std::string& text, Expectation* out, std::string* error);
/// A run's VALUE as a number (booleans 1/0); nothing when absent or not a number.
std::optional<double> RunValue(const SeedOutcome& run, const std::string& name);
/// The same, with why a file column is missing in `why` (left empty otherwise).
std::optional<double> RunValue(const SeedOutcome& run, const std::string& name, std::string* why);
/// The expectation over the finished runs (a run that did not finish is checked apart).
Verdict Evaluate(const Expectation& e, const std::vector<SeedOutcome>& runs);

}  // namespace essaim
