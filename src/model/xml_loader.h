// The .argos loader: the only tinyxml2 user. Turns a file into a const Model, reporting
// every problem (file:line: <element>: message) instead of stopping at the first.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error_list.h"
#include "model/model.h"

namespace essaim {

struct LoadOptions {
  std::vector<std::string> overrides;  // "path=value" (docs/cli.md)
  std::optional<uint64_t> ticks;       // exact experiment length in ticks
  std::optional<uint64_t> seed;
  std::optional<int> threads;
  /// Where relative paths fall back to after the .argos folder (ARGoS: the process cwd).
  std::string working_dir = ".";
  /// Unknown attributes in the file are errors, not warnings (--strict).
  bool strict = false;
};

/// Returns nullptr and fills `errors` when the file is unusable. `warnings` receives
/// things accepted but ignored (e.g. <visualization>).
std::unique_ptr<Model> LoadExperimentFile(const std::string& path, const LoadOptions& options, ErrorList* errors,
                                          ErrorList* warnings = nullptr);
/// Same, from text; `path` names it in messages and anchors relative paths.
std::unique_ptr<Model> LoadExperimentText(const std::string& xml, const std::string& path, const LoadOptions& options,
                                          ErrorList* errors, ErrorList* warnings = nullptr);

}  // namespace essaim
