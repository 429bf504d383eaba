#include "core/paths.h"

#include <filesystem>
#include <fstream>
#include <iterator>

namespace essaim {

namespace fs = std::filesystem;

// What fs::path::parent_path() gives on POSIX (the path up to its last component, that
// component's separators dropped; a path of separators only is its own parent), without
// its parse: ~25 allocations a call, and every Lua state's set-up made three.
std::string DirName(const std::string& path) {
  const size_t slash = path.rfind('/');
  if (slash == std::string::npos) return "";
  const size_t end = path.find_last_not_of('/', slash);
  if (end == std::string::npos) return path.find_first_not_of('/') == std::string::npos ? path : "/";
  return path.substr(0, end + 1);
}

std::string JoinPath(const std::string& dir, const std::string& rel) { return (fs::path(dir) / rel).string(); }

bool FileExists(const std::string& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

std::string WeaklyCanonicalPath(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path, ec).lexically_normal().string() : p.string();
}

bool PathExists(const std::string& path) {
  std::error_code ec;
  return fs::exists(path, ec);
}

std::string SpecialFileKind(const std::string& path) {
  std::error_code ec;
  switch (fs::status(path, ec).type()) {
    case fs::file_type::regular:
    case fs::file_type::not_found:
    case fs::file_type::none:
      return "";
    case fs::file_type::directory:
      return "a folder";
    case fs::file_type::fifo:
      return "a FIFO";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

std::string CanonicalPath(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::canonical(path.empty() ? "." : path, ec);
  return ec ? "" : p.string();
}

bool IsInsideFolder(const std::string& path, const std::string& root) {
  if (root.empty() || path.size() <= root.size() || path.compare(0, root.size(), root) != 0) return false;
  return root.back() == '/' || path[root.size()] == '/';
}

bool ReadFile(const std::string& path, std::string* out) {
  if (!FileExists(path)) return false;  // an ifstream "reads" a folder as an empty file
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

}  // namespace essaim
