#include "app/set_file.h"

#include "core/json.h"
#include "core/paths.h"
#include "core/strings.h"

namespace essaim {

namespace {
// Nested objects are path segments: {"arena": {"fb0": {"rab_range": 2}}} is arena.fb0.rab_range=2.
bool Flatten(const Json& object, const std::string& prefix, const std::string& path,
             std::vector<std::string>* overrides, std::string* error) {
  for (const auto& [key, value] : object.items()) {
    std::string name = prefix.empty() ? key : prefix + "." + key;
    std::string text_value;
    if (value.is_object()) {
      if (!Flatten(value, name, path, overrides, error)) return false;
      continue;
    }
    if (value.is_string())
      text_value = value.get<std::string>();
    else if (value.is_boolean())
      text_value = value.get<bool>() ? "true" : "false";
    else if (value.is_number_integer())
      text_value = value.dump();
    else if (value.is_number_float())
      text_value = FormatDouble(value.get<double>());
    else {
      *error = path + ": \"" + name + "\": the value must be a string, a number or a boolean, not " + value.type_name();
      return false;
    }
    overrides->push_back(name + "=" + text_value);
  }
  return true;
}
}  // namespace

bool ReadOverridesFile(const std::string& path, std::vector<std::string>* overrides, std::string* error) {
  std::string text;
  if (!ReadFile(path, &text)) {
    *error = path + ": cannot read the --set-file";
    return false;
  }
  Json doc;
  std::string parse_error;
  if (!ParseJson(text, &doc, &parse_error)) {
    *error = path + ": " + parse_error;
    return false;
  }
  if (!doc.is_object()) {
    *error = path + ": expected a JSON object {\"PATH\": value, ...}";
    return false;
  }
  return Flatten(doc, "", path, overrides, error);
}

}  // namespace essaim
