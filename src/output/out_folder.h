// The run's output folder (--out): checked before the first tick, and cleared of an earlier
// run's outputs so that it never mixes two runs (docs/cli.md, "The output folder").
#pragma once
#include <string>
#include <vector>

namespace essaim {

/// The folder name earlier outputs are moved into, inside the output folder.
constexpr const char* kPreviousRunFolder = "previous";

/// Whether `name` (a file name, no folder) is one essaim writes into a run folder:
/// summary.json, metrics.json, timeseries.csv, recording.bin, replay.html,
/// snapshot-*.png, or a temporary file of one of them (NAME.tmp.PID).
bool IsRunOutputName(const std::string& name);

/// Makes `dir` (mkdir -p) and proves it writable by creating and removing a probe file.
/// Refused: a path that is a file, a folder that cannot be made or written, a run output
/// name in it that is not a regular file (a folder called summary.json...).
bool PrepareOutFolder(const std::string& dir, std::string* error);

/// Moves every run output found in `dir` (IsRunOutputName) into dir/previous/, first
/// removing the run outputs previous/ held, so previous/ holds one earlier run. Files
/// essaim does not write (the user's, the loop functions') are left where they are.
/// `moved` gets the names moved, sorted.
bool SetAsideEarlierOutputs(const std::string& dir, std::vector<std::string>* moved, std::string* error);

}  // namespace essaim
