// The CLI's subcommands; each returns the process exit code (docs/cli.md).
#pragma once
#include <string>
#include <vector>

namespace essaim {

constexpr int kExitOk = 0;
constexpr int kExitRunFailed = 1;
constexpr int kExitBadInput = 2;

int RunCommand(const std::vector<std::string>& args);
int CheckCommand(const std::vector<std::string>& args);
int DevicesCommand(const std::vector<std::string>& args);
int BenchCommand(const std::vector<std::string>& args);
int ReplayCommand(const std::vector<std::string>& args);
int SnapshotCommand(const std::vector<std::string>& args);
/// A run folder's recording.bin, or the path itself when it is not a folder (replay, snapshot).
std::string RecordingPathOf(const std::string& run);

/// Progress line on a terminal: ticks, ticks/s, robots, ETA (nothing when not a TTY).
class Progress {
 public:
  Progress(bool enabled, unsigned long long total_ticks, size_t robots);
  void Update(unsigned long long tick);
  void Finish();

 private:
  bool enabled_;
  unsigned long long total_;
  size_t robots_;
  double start_, last_;
};

}  // namespace essaim
