#include "app/set_file.h"

#include "core/json.h"
#include "core/paths.h"
#include "core/strings.h"

namespace essaim {

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
  for (const auto& [key, value] : doc.items()) {
    std::string text_value;
    if (value.is_string()) text_value = value.get<std::string>();
    else if (value.is_boolean()) text_value = value.get<bool>() ? "true" : "false";
    else if (value.is_number_integer()) text_value = value.dump();
    else if (value.is_number_float()) text_value = FormatDouble(value.get<double>());
    else {
      *error = path + ": \"" + key + "\": the value must be a string, a number or a boolean, not " + value.type_name();
      return false;
    }
    overrides->push_back(key + "=" + text_value);
  }
  return true;
}

}  // namespace essaim
