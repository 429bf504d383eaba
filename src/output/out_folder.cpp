#include "output/out_folder.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "output/memory_log.h"
#include "output/recording.h"

namespace essaim {

namespace fs = std::filesystem;

namespace {
bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

bool IsFinalOutputName(const std::string& name) {
  static const char* const kNames[] = {"summary.json", "metrics.json", "timeseries.csv", kRecordingFile, kMemoryLogFile, "replay.html"};
  for (const char* n : kNames)
    if (name == n) return true;
  return name.rfind("snapshot-", 0) == 0 && EndsWith(name, ".png");
}

/// Run outputs directly in `dir`, sorted (directory order is the file system's).
std::vector<std::string> RunOutputsIn(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::string name = it->path().filename().string();
    if (IsRunOutputName(name)) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}
}  // namespace

bool IsRunOutputName(const std::string& name) {
  size_t tmp = name.rfind(".tmp.");
  if (tmp != std::string::npos && tmp + 5 < name.size() &&
      std::all_of(name.begin() + static_cast<long>(tmp) + 5, name.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return IsFinalOutputName(name.substr(0, tmp));
  return IsFinalOutputName(name);
}

bool PrepareOutFolder(const std::string& dir, std::string* error) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
    *error = "--out " + dir + " is a file, not a folder";
    return false;
  }
  fs::create_directories(dir, ec);
  if (ec) {
    *error = "--out " + dir + ": cannot create the folder: " + ec.message();
    return false;
  }
  // access(W_OK) says yes to root on a read-only mount: create a file to be sure.
  std::string probe = (fs::path(dir) / (".essaim-probe." + std::to_string(::getpid()))).string();
  int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0) {
    *error = "--out " + dir + ": cannot write in this folder: " + std::strerror(errno);
    return false;
  }
  ::close(fd);
  ::unlink(probe.c_str());
  for (const std::string& name : RunOutputsIn(dir)) {
    fs::file_status st = fs::symlink_status(fs::path(dir) / name, ec);
    if (!fs::is_regular_file(st) && !fs::is_symlink(st)) {
      *error = "--out " + dir + ": " + name + " is not a regular file; essaim writes a file of that name there";
      return false;
    }
  }
  return true;
}

bool SetAsideEarlierOutputs(const std::string& dir, std::vector<std::string>* moved, std::string* error) {
  moved->clear();
  std::vector<std::string> names = RunOutputsIn(dir);
  if (names.empty()) return true;
  const fs::path previous = fs::path(dir) / kPreviousRunFolder;
  std::error_code ec;
  fs::create_directories(previous, ec);
  if (ec) {
    *error = "cannot create " + previous.string() + " for the earlier run's outputs: " + ec.message();
    return false;
  }
  for (const std::string& name : RunOutputsIn(previous)) fs::remove(previous / name, ec);
  for (const std::string& name : names) {
    fs::rename(fs::path(dir) / name, previous / name, ec);
    if (ec) {
      *error = "cannot move " + (fs::path(dir) / name).string() + " into " + previous.string() + ": " + ec.message();
      return false;
    }
    moved->push_back(name);
  }
  return true;
}

}  // namespace essaim
