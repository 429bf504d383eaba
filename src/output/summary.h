// What a run leaves in its output folder: summary.json, metrics.json, timeseries.csv
// (docs/cli.md). Built from the World; written atomically.
#pragma once
#include <string>
#include <vector>

#include "core/json.h"
#include "sim/world.h"

namespace essaim {

struct RunInfo {
  std::string version;
  double wall_seconds = 0;
  std::string status = "ok";        // ok | controller_error | failed | interrupted
  std::string finished_by = "length";
  std::vector<std::string> outputs; // file names written
};

Json BuildSummary(const World& world, const RunInfo& info);
std::string TimeseriesCsv(const Timeseries& series);
/// Writes metrics.json and timeseries.csv (when there is something to write), then
/// summary.json last, so a folder with summary.json holds a finished run.
bool WriteRunOutputs(const std::string& dir, const World& world, RunInfo info, const Json* metrics,
                     std::string* error);

}  // namespace essaim
