// The run's working directory (docs/loop-functions.md, "Files the loop functions write"):
// <out>/files/, filled with a view of the experiment before the run so that relative reads
// still find its files, and emptied of that view after it, so that it keeps exactly the files
// the run wrote or changed. Files only; the process's chdir is its owner's choice (app).
#pragma once
#include <sys/types.h>

#include <cstdint>
#include <ctime>
#include <string>
#include <vector>

namespace essaim {

/// The folder inside the output folder: the run's working directory, then its files.
constexpr const char* kRunFilesFolder = "files";

struct RunFilesLimits {
  size_t max_entries = 10000;                // entries placed, all sources together
  uintmax_t copy_max_bytes = 1 << 20;        // a regular file up to this size is copied
  uintmax_t copy_total_bytes = 16ull << 20;  // and while the copies stay under this
};

class RunFilesView {
 public:
  RunFilesView() = default;
  ~RunFilesView() { Finish(); }
  RunFilesView(const RunFilesView&) = delete;
  RunFilesView& operator=(const RunFilesView&) = delete;

  /// Makes `folder` (absent or empty) and places in it the entries of each of `sources`
  /// in order, a name already placed skipped: folders and large files as symlinks, small
  /// regular files as copies (a run that overwrites one writes its own copy, never the
  /// original). Entries whose canonical path is in `exclude` are left out (the output
  /// folder, when it lies among the sources).
  bool Make(const std::string& folder, const std::vector<std::string>& sources, const std::vector<std::string>& exclude,
            const RunFilesLimits& limits, std::string* error);
  /// Entries left out past limits.max_entries.
  size_t LeftOut() const { return left_out_; }
  /// Removes the symlinks and the unchanged copies Make placed (idempotent); the files left,
  /// the run's own, relative to the folder, sorted (a folder the run made, with its files).
  std::vector<std::string> Finish();
  const std::string& Folder() const { return folder_; }

 private:
  struct Placed {
    std::string name;
    std::string target;  // a symlink's target; "" for a copy
    uintmax_t size = 0;
    timespec mtime{};
    ino_t inode = 0;
  };
  bool Place(const std::string& source, const std::string& name, const RunFilesLimits& limits, std::string* error);
  bool Unchanged(const Placed& p) const;

  std::string folder_;
  std::vector<Placed> placed_;
  uintmax_t copied_bytes_ = 0;
  size_t left_out_ = 0;
  bool finished_ = true;
};

/// Every regular file and symlink under `folder`, relative to it, sorted.
std::vector<std::string> FilesUnder(const std::string& folder);

}  // namespace essaim
