#include "output/out_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "output/memory_log.h"
#include "output/recording.h"
#include "output/run_files.h"

namespace essaim {

namespace fs = std::filesystem;

namespace {
bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

bool IsFinalOutputName(const std::string& name) {
  static const char* const kNames[] = {"summary.json", "metrics.json", "timeseries.csv",
                                       kRecordingFile, kMemoryLogFile, "replay.html"};
  for (const char* n : kNames)
    if (name == n) return true;
  if (name == kRunFilesFolder) return true;  // the run's working folder: its own files
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
    if (name == kRunFilesFolder ? !fs::is_directory(st) : !fs::is_regular_file(st) && !fs::is_symlink(st)) {
      *error = "--out " + dir + ": " + name +
               (name == kRunFilesFolder ? " is not a folder; essaim makes a folder"
                                        : " is not a regular file; essaim writes a file") +
               " of that name there";
      return false;
    }
  }
  return true;
}

namespace {
/// N of a folder named previous-N (N >= 2), else 0.
long Generation(const std::string& name) {
  const std::string head = std::string(kPreviousRunFolder) + "-";
  if (name.rfind(head, 0) != 0 || name.size() == head.size() || name.size() > head.size() + 9) return 0;
  for (size_t i = head.size(); i < name.size(); ++i)
    if (name[i] < '0' || name[i] > '9') return 0;
  const long n = std::stol(name.substr(head.size()));
  return n >= 2 ? n : 0;
}

/// previous/ -> previous-2/, previous-2/ -> previous-3/, ...: the oldest moved first.
bool ShiftGenerations(const fs::path& dir, std::string* error) {
  std::vector<long> numbers;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (long n = Generation(it->path().filename().string())) numbers.push_back(n);
  std::sort(numbers.rbegin(), numbers.rend());
  auto name = [&](long n) { return dir / (std::string(kPreviousRunFolder) + (n < 2 ? "" : "-" + std::to_string(n))); };
  numbers.push_back(1);  // previous/ itself, last
  for (long n : numbers) {
    if (!fs::exists(name(n), ec)) continue;
    fs::rename(name(n), name(n < 2 ? 2 : n + 1), ec);
    if (ec) {
      *error = "cannot move " + name(n).string() + " to " + name(n < 2 ? 2 : n + 1).string() + ": " + ec.message();
      return false;
    }
  }
  return true;
}
}  // namespace

bool SetAsideEarlierOutputs(const std::string& dir, std::vector<std::string>* moved, std::string* error) {
  moved->clear();
  std::vector<std::string> names = RunOutputsIn(dir);
  if (names.empty()) return true;
  const fs::path previous = fs::path(dir) / kPreviousRunFolder;
  if (!ShiftGenerations(dir, error)) return false;
  std::error_code ec;
  fs::create_directories(previous, ec);
  if (ec) {
    *error = "cannot create " + previous.string() + " for the earlier run's outputs: " + ec.message();
    return false;
  }
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

OutFolderLock::~OutFolderLock() { Release(); }

void OutFolderLock::Release() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // while still held: a run waiting on this file retries on the new one
  ::close(fd_);
  fd_ = -1;
}

bool OutFolderLock::Acquire(const std::string& dir, std::string* error) {
  Release();
  path_ = (fs::path(dir) / kLockFile).string();
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644);
    if (fd < 0) {
      *error = "--out " + dir + ": cannot open " + path_ + ": " + std::strerror(errno);
      return false;
    }
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      char owner[32] = {0};
      const ssize_t n = ::pread(fd, owner, sizeof owner - 1, 0);
      ::close(fd);
      std::string pid = n > 0 ? std::string(owner, static_cast<size_t>(n)) : "unknown";
      while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
      *error = "--out " + dir + " is in use by another essaim run (pid " + pid + "); give another folder";
      return false;
    }
    // Locked, but the file may have been removed by the run that held it: lock the one there.
    struct stat held, there;
    if (::fstat(fd, &held) == 0 && ::stat(path_.c_str(), &there) == 0 && held.st_ino == there.st_ino &&
        held.st_dev == there.st_dev) {
      const std::string pid = std::to_string(::getpid()) + "\n";
      if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) < 0) {
      }  // the pid is for messages only
      fd_ = fd;
      return true;
    }
    ::close(fd);
  }
  *error = "--out " + dir + ": cannot take the lock " + path_;
  return false;
}

}  // namespace essaim
