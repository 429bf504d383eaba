#include "core/paths.h"

#include <filesystem>
#include <fstream>
#include <iterator>

namespace essaim {

namespace fs = std::filesystem;

std::string DirName(const std::string& path) { return fs::path(path).parent_path().string(); }

std::string JoinPath(const std::string& dir, const std::string& rel) { return (fs::path(dir) / rel).string(); }

bool FileExists(const std::string& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

std::string CanonicalPath(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path, ec).lexically_normal().string() : p.string();
}

bool ReadFile(const std::string& path, std::string* out) {
  if (!FileExists(path)) return false;  // an ifstream "reads" a folder as an empty file
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return !in.bad();
}

}  // namespace essaim
