// What a run leaves in its output folder: summary.json, metrics.json, timeseries.csv
// (docs/cli.md). Built from the World; written atomically.
#pragma once
#include <string>
#include <vector>

#include "core/value.h"
#include "sim/run_end.h"
#include "sim/world.h"

namespace essaim {

/// What summary.json says besides the World: the run's outcome (status, finished_by) and
/// what only the caller knows.
struct RunInfo : RunOutcome {
  std::string version;
  double wall_seconds = 0;
  std::vector<std::string> outputs;  // file names written
  /// The files the run's scripts wrote or changed, relative to the output folder
  /// ("files/score.txt"): summary.json's "files" when `files_listed` (essaim run).
  std::vector<std::string> files;
  bool files_listed = false;
  /// Outputs that could not be written (a full disk): they make the status "failed" and
  /// go into summary.json's "failure".
  std::vector<std::string> output_errors;
  /// When not empty, summary.json's "failure" instead of the World's (a run the watchdog
  /// stopped for good).
  std::string failure;
  /// A controller (or the loop functions, or essaim) that crashed the process: summary.json's
  /// "crash", written by the crash handler (app/run_session.cpp) with status "crashed".
  struct Crash {
    std::string robot;   // its id; "" when no controller was running
    std::string call;    // "ControlStep", "Init", a loop-function hook...
    std::string signal;  // "SIGSEGV"
    uint64_t tick = 0;
  };
  bool crashed = false;
  Crash crash;
  /// essaim debug's record (its divergences): summary.json's "debug"; null in other runs.
  Value debug;
};

/// summary.json's text.
std::string SummaryJsonText(const World& world, const RunInfo& info);
/// RFC 4180: a column name holding a comma, a quote or a line break is quoted, quotes
/// doubled. Values are shortest round-trip; NaN and infinities are NaN, Inf and -Inf
/// (what pandas, numpy and R read back).
std::string TimeseriesCsv(const Timeseries& series);
/// summary.json of a run that ended before its world existed: bad input (the file, a --set,
/// a floor image) or a script that does not load. Status "failed", finished_by "error", 0
/// ticks, `message` as "failure"; `model` is null when the file itself did not load;
/// `inputs` (may be null) lists the files read so far, with the run's identity.
bool WriteFailureSummary(const std::string& dir, const std::string& version, const std::string& experiment,
                         const std::vector<std::string>& overrides, const Model* model, const InputFiles* inputs,
                         const std::string& message, std::string* error);
/// Writes metrics.json and timeseries.csv (when there is something to write), then
/// summary.json last, so a folder with summary.json holds a finished run. One that cannot
/// be written does not stop the others: summary.json is still attempted, with status
/// "failed" and the reasons. False when anything failed, `error` listing what ("; ").
bool WriteRunOutputs(const std::string& dir, const World& world, RunInfo info, const Value* metrics,
                     std::string* error);

}  // namespace essaim
