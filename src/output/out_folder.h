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
/// snapshot-*.png, files/ (the run's working folder), or a temporary file of one of them
/// (NAME.tmp.PID).
bool IsRunOutputName(const std::string& name);

/// Makes `dir` (mkdir -p) and proves it writable by creating and removing a probe file.
/// Refused: a path that is a file, a folder that cannot be made or written, a run output
/// name in it that is not a regular file (a folder called summary.json...).
bool PrepareOutFolder(const std::string& dir, std::string* error);

/// Moves every run output found in `dir` (IsRunOutputName) into dir/previous/, after
/// moving an earlier previous/ to previous-2/ (previous-2/ to previous-3/, and so on): no
/// earlier run is lost. Files essaim does not write (the user's, the loop functions') are
/// left where they are. `moved` gets the names moved, sorted.
bool SetAsideEarlierOutputs(const std::string& dir, std::vector<std::string>* moved, std::string* error);

/// The lock file a run holds in its folder (flock), with the owner's pid for messages.
constexpr const char* kLockFile = ".essaim-lock";

/// One run per folder at a time: a lock held from before the first output is touched until
/// the run ends (or its process dies: the kernel releases it). The file is removed on release.
class OutFolderLock {
 public:
  OutFolderLock() = default;
  ~OutFolderLock();
  OutFolderLock(const OutFolderLock&) = delete;
  OutFolderLock& operator=(const OutFolderLock&) = delete;
  /// False with "--out DIR is in use by another essaim run (pid N)..." when another holds it.
  bool Acquire(const std::string& dir, std::string* error);
  void Release();
  bool Held() const { return fd_ >= 0; }

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace essaim
