// The CLI's subcommands; each returns the process exit code (docs/cli.md).
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace essaim {

constexpr int kExitOk = 0;
constexpr int kExitRunFailed = 1;
constexpr int kExitBadInput = 2;

/// Each Add*Command declares one subcommand (its options, --help text and example) on the
/// CLI11 app and returns what runs it once the command line has been parsed.
using CommandMain = std::function<int()>;
CommandMain AddRunCommand(CLI::App& app);
CommandMain AddCheckCommand(CLI::App& app);
CommandMain AddDevicesCommand(CLI::App& app);
CommandMain AddBenchCommand(CLI::App& app);
CommandMain AddReplayCommand(CLI::App& app);
CommandMain AddSnapshotCommand(CLI::App& app);
CommandMain AddVideoCommand(CLI::App& app);
CommandMain AddServeCommand(CLI::App& app);
CommandMain AddTestCommand(CLI::App& app);
CommandMain AddNewCommand(CLI::App& app);
CommandMain AddDebugCommand(CLI::App& app);
/// A run folder's recording.bin, or the path itself when it is not a folder (replay, snapshot).
std::string RecordingPathOf(const std::string& run);

/// Progress line on a terminal: ticks, ticks/s, robots, ETA (nothing when not a TTY).
class Progress {
 public:
  Progress(bool enabled, unsigned long long total_ticks, size_t robots);
  void Update(unsigned long long tick);
  /// Erases the progress line if it is shown, so that a log line starts on a clean line; the
  /// next Update draws it again.
  void Clear();
  void Finish();

 private:
  bool enabled_;
  bool shown_ = false;
  unsigned long long total_;
  size_t robots_;
  double start_, last_;
};

}  // namespace essaim
