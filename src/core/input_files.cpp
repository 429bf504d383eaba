#include "core/input_files.h"

#include <algorithm>

#include "core/hash.h"
#include "core/paths.h"

namespace essaim {

void InputFiles::Add(const std::string& path, const char* role) {
  const std::string& from_base = base_.empty() || path.empty() || path[0] == '/' ? path : JoinPath(base_, path);
  std::string canonical = WeaklyCanonicalPath(from_base);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const InputFile& f : files_)
      if (f.path == canonical) return;
  }
  std::string bytes, hash;
  if (ReadFile(path, &bytes)) {
    Fnv1a64 h;
    h.Add(bytes.data(), bytes.size());
    hash = "fnv1a64:" + h.Hex();
  }
  std::lock_guard<std::mutex> lock(mutex_);
  for (const InputFile& f : files_)
    if (f.path == canonical) return;  // another thread was quicker
  files_.push_back({canonical, role, hash});
}

std::vector<InputFile> InputFiles::List() const {
  std::vector<InputFile> list;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    list = files_;
  }
  auto is_module = [](const InputFile& f) { return f.role == "module"; };
  auto modules = std::stable_partition(list.begin(), list.end(), [&](const InputFile& f) { return !is_module(f); });
  std::sort(modules, list.end(), [](const InputFile& a, const InputFile& b) { return a.path < b.path; });
  return list;
}

std::string InputFiles::Identity(const std::string& version, const std::vector<std::string>& overrides, uint64_t ticks,
                                 uint64_t seed) const {
  // Each field ends with a NUL, so that no two different lists give the same bytes.
  Fnv1a64 h;
  auto add = [&h](const std::string& s) { h.Add(s.c_str(), s.size() + 1); };
  add(version);
  for (const InputFile& f : List()) {
    add(f.path);
    add(f.hash);
  }
  for (const std::string& o : overrides) add(o);
  add("ticks=" + std::to_string(ticks));
  add("seed=" + std::to_string(seed));
  return "fnv1a64:" + h.Hex();
}

}  // namespace essaim
