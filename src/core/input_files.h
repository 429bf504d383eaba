// The files a run read (the .argos file, scripts, required modules, floor images) with the
// hash of their bytes: summary.json lists them, and a run's identity hashes them, so a sweep
// can tell a stored run made from files that have since changed.
#pragma once
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace essaim {

struct InputFile {
  std::string path;  // absolute, canonical
  std::string role;  // arena | controller | controller_library | loop_functions | loop_functions_library |
                     // module | floor_image
  std::string hash;  // "fnv1a64:<16 hex>" of the bytes read
};

/// Safe to add to from several threads (a `require` inside step()). Each path is listed
/// once, with the role and content it had when first added.
class InputFiles {
 public:
  /// Reads and hashes `path` the first time it is seen; a file that cannot be read is
  /// listed with an empty hash (the loader or Lua reports why).
  void Add(const std::string& path, const char* role);
  /// In the order added, except modules: sorted by path at the end, so a list made while
  /// robots ran on several threads is the same every time.
  std::vector<InputFile> List() const;
  /// "fnv1a64:<16 hex>" over the version, each input's path and hash (List's order), the
  /// overrides, the experiment length in ticks and the seed: equal identities, equal runs.
  std::string Identity(const std::string& version, const std::vector<std::string>& overrides, uint64_t ticks,
                       uint64_t seed) const;
  /// The folder relative paths are taken from, when it is not the working directory (a run
  /// working in its own folder names its inputs as from the folder it was started in).
  void SetBase(const std::string& dir) { base_ = dir; }

 private:
  std::string base_;
  mutable std::mutex mutex_;
  std::vector<InputFile> files_;
};

}  // namespace essaim
