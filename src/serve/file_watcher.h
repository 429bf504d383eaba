// Tells when one of a set of files changes on disk: the only inotify user. It watches the
// files' folders rather than the files, so saves that replace a file (an editor writing a
// temporary file and renaming it over the original, or deleting then recreating it) are
// seen like saves in place.
#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>

namespace essaim {

class FileWatcher {
 public:
  FileWatcher();
  ~FileWatcher();
  FileWatcher(const FileWatcher&) = delete;
  FileWatcher& operator=(const FileWatcher&) = delete;

  /// False when inotify could not be set up, with the reason in Error().
  bool Ok() const { return fd_ >= 0; }
  const std::string& Error() const { return error_; }
  /// Watches these files from now on (replacing the previous set). A folder that cannot be
  /// watched (gone) is left out and said in Error().
  void Watch(const std::vector<std::string>& files);
  const std::set<std::string>& Files() const { return files_; }
  /// Waits up to `timeout_ms` for a watched file to be written, replaced, created or
  /// removed. After the first such event it keeps reading until `settle_ms` pass without
  /// one, so that the several events of one save (and a file written in steps) count once.
  /// True with the changed paths (absolute) in `changed` when one did.
  bool WaitForChange(int timeout_ms, std::vector<std::string>* changed = nullptr, int settle_ms = 100);

 private:
  /// Reads the events waiting (none: returns at once); adds the watched paths they name.
  void Drain(std::set<std::string>* changed);
  int fd_ = -1;
  std::string error_;
  std::map<int, std::string> folders_;  // watch descriptor -> folder
  std::set<std::string> files_;         // absolute, normalised
};

}  // namespace essaim
