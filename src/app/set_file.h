// `--set-file params.json`: many --set overrides at once, from a JSON object.
#pragma once
#include <string>
#include <vector>

namespace essaim {

/// Reads {"PATH": value, ...} (values: strings, numbers, booleans; a nested object adds path
/// segments) into "PATH=VALUE" overrides, in the file's order. False with a message naming the file (and line, or key)
/// otherwise.
bool ReadOverridesFile(const std::string& path, std::vector<std::string>* overrides, std::string* error);

}  // namespace essaim
