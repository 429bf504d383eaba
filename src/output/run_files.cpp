#include "output/run_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "core/paths.h"

namespace essaim {

namespace fs = std::filesystem;

namespace {
std::vector<std::string> NamesIn(const std::string& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    names.push_back(it->path().filename().string());
  std::sort(names.begin(), names.end());  // directory order is the file system's
  return names;
}

bool SameTime(const timespec& a, const timespec& b) { return a.tv_sec == b.tv_sec && a.tv_nsec == b.tv_nsec; }
}  // namespace

bool RunFilesView::Make(const std::string& folder, const std::vector<std::string>& sources,
                        const std::vector<std::string>& exclude, const RunFilesLimits& limits, std::string* error) {
  Finish();
  folder_ = folder;
  placed_.clear();
  copied_bytes_ = 0;
  left_out_ = 0;
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec || !fs::is_empty(folder, ec)) {
    *error = "cannot make the run's working folder " + folder + (ec ? ": " + ec.message() : ": it is not empty");
    return false;
  }
  finished_ = false;
  std::set<std::string> taken, excluded(exclude.begin(), exclude.end());
  excluded.insert(CanonicalPath(folder));
  for (const std::string& source : sources) {
    for (const std::string& name : NamesIn(source)) {
      const std::string path = JoinPath(source, name);
      if (taken.count(name) || excluded.count(CanonicalPath(path))) continue;
      if (placed_.size() >= limits.max_entries) {
        ++left_out_;
        continue;
      }
      taken.insert(name);
      if (!Place(path, name, limits, error)) return false;
    }
  }
  return true;
}

bool RunFilesView::Place(const std::string& source, const std::string& name, const RunFilesLimits& limits,
                         std::string* error) {
  Placed p;
  p.name = name;
  const std::string dest = JoinPath(folder_, name);
  std::error_code ec;
  const fs::path absolute = fs::absolute(source, ec);
  struct stat st;
  const bool small = ::stat(source.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
                     static_cast<uintmax_t>(st.st_size) <= limits.copy_max_bytes &&
                     copied_bytes_ + static_cast<uintmax_t>(st.st_size) <= limits.copy_total_bytes;
  if (small && fs::copy_file(source, dest, ec) && !ec) {
    copied_bytes_ += static_cast<uintmax_t>(st.st_size);
    // The original's times: any write of the run sets "now", never mistaken for no write
    // (a copy's own time and a rewrite soon after can share a clock tick).
    const timespec times[2] = {st.st_atim, st.st_mtim};
    ::utimensat(AT_FDCWD, dest.c_str(), times, 0);
  } else {
    ec.clear();
    fs::remove(dest, ec);  // a copy that failed half-way (an unreadable file): a link instead
    p.target = absolute.string();
    fs::create_symlink(absolute, dest, ec);
    if (ec) {
      *error = "cannot place " + source + " in the run's working folder " + folder_ + ": " + ec.message();
      return false;
    }
  }
  struct stat placed;
  if (p.target.empty() && ::lstat(dest.c_str(), &placed) == 0) {
    p.size = static_cast<uintmax_t>(placed.st_size);
    p.mtime = placed.st_mtim;
    p.inode = placed.st_ino;
  }
  placed_.push_back(std::move(p));
  return true;
}

bool RunFilesView::Unchanged(const Placed& p) const {
  const std::string path = JoinPath(folder_, p.name);
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0) return false;  // removed by the run: nothing to remove
  if (!p.target.empty()) {
    std::error_code ec;
    return S_ISLNK(st.st_mode) && fs::read_symlink(path, ec).string() == p.target && !ec;
  }
  // A rewrite with the same bytes still counts as the run's: its time changed.
  return S_ISREG(st.st_mode) && st.st_ino == p.inode && static_cast<uintmax_t>(st.st_size) == p.size &&
         SameTime(st.st_mtim, p.mtime);
}

std::vector<std::string> RunFilesView::Finish() {
  if (finished_) return {};
  finished_ = true;
  for (const Placed& p : placed_) {
    if (!Unchanged(p)) continue;
    std::error_code ec;
    fs::remove(JoinPath(folder_, p.name), ec);
  }
  placed_.clear();
  return FilesUnder(folder_);
}

std::vector<std::string> FilesUnder(const std::string& folder) {
  std::vector<std::string> files;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::file_status st = it->symlink_status(ec);
    if (fs::is_regular_file(st) || fs::is_symlink(st)) files.push_back(it->path().lexically_relative(folder).string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace essaim
