#include "output/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "core/paths.h"

namespace essaim {

namespace fs = std::filesystem;

bool ResolveOutput(const std::string& path, std::string* target, std::string* error) {
  std::error_code ec;
  *target = path;
  if (!fs::is_symlink(fs::symlink_status(path, ec))) return true;
  fs::path real = fs::canonical(path, ec);  // follows every link; fails on a dangling one
  if (ec) {
    *error = "cannot write " + path + ": a symlink whose target cannot be reached (" + ec.message() + ")";
    return false;
  }
  *target = real.string();
  return true;
}

bool CheckOutputFile(const std::string& path, std::string* error) {
  std::string target;
  if (!ResolveOutput(path, &target, error)) return false;
  const std::string kind = SpecialFileKind(target);  // the target has no symlink left
  if (!kind.empty()) {
    *error = "cannot write " + path + ": it is " + kind + ", not a regular file (refusing to replace it)";
    return false;
  }
  std::error_code ec;
  fs::path parent = fs::path(target).parent_path();
  if (parent.empty()) parent = ".";
  if (!fs::is_directory(parent, ec)) {
    *error = "cannot write " + path + ": no folder " + parent.string();
    return false;
  }
  return true;
}

bool WriteFileAtomic(const std::string& path, const std::string& content, std::string* error) {
  std::string target;
  if (!CheckOutputFile(path, error) || !ResolveOutput(path, &target, error)) return false;
  std::string tmp = target + ".tmp." + std::to_string(::getpid());
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) {
    *error = "cannot write " + tmp + ": " + std::strerror(errno);
    return false;
  }
  // The first failure's errno is the reason (fclose after a failed write may set another).
  int failure = 0;
  auto check = [&](bool ok) {
    if (!ok && !failure) failure = errno ? errno : EIO;
  };
  errno = 0;
  check(std::fwrite(content.data(), 1, content.size(), f) == content.size());
  check(std::fflush(f) == 0);
  check(::fsync(fileno(f)) == 0);
  check(std::fclose(f) == 0);
  if (!failure) check(std::rename(tmp.c_str(), target.c_str()) == 0);
  if (failure) {
    *error = "cannot write " + path + ": " + std::strerror(failure);
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

bool MakeDirs(const std::string& path, std::string* error) {
  if (path.empty()) return true;
  std::error_code ec;
  std::filesystem::create_directories(path, ec);
  if (ec) {
    *error = "cannot create folder " + path + ": " + ec.message();
    return false;
  }
  return true;
}

}  // namespace essaim
