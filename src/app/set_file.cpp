#include "app/set_file.h"

#include "core/paths.h"
#include "core/strings.h"
#include "core/value_json.h"

namespace essaim {

namespace {
// A leaf as the text of an override; false when it is not a string, a number or a boolean.
bool LeafText(const Value& value, std::string* text) {
  switch (value.kind) {
    case Value::Kind::String:
      *text = value.text;
      return true;
    case Value::Kind::Bool:
      *text = value.boolean ? "true" : "false";
      return true;
    case Value::Kind::Integer:
      *text = std::to_string(value.integer);
      return true;
    case Value::Kind::Unsigned:
      *text = std::to_string(value.big_unsigned);
      return true;
    case Value::Kind::Number:
      *text = FormatDouble(value.number);
      return true;
    default:
      return false;
  }
}

// Nested objects are path segments: {"arena": {"fb0": {"rab_range": 2}}} is arena.fb0.rab_range=2.
bool Flatten(const Value& object, const std::string& prefix, const std::string& path,
             std::vector<std::string>* overrides, std::string* error) {
  for (const auto& [key, value] : object.map) {
    std::string name = prefix.empty() ? key : prefix + "." + key;
    if (value.kind == Value::Kind::Map) {
      if (!Flatten(value, name, path, overrides, error)) return false;
      continue;
    }
    std::string text_value;
    if (!LeafText(value, &text_value)) {
      *error = path + ": \"" + name + "\": the value must be a string, a number or a boolean, not " +
               (value.kind == Value::Kind::List ? "array" : "null");
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
  Value doc;
  std::string parse_error;
  if (!ParseJsonValue(text, &doc, &parse_error)) {
    *error = path + ": " + parse_error;
    return false;
  }
  if (doc.kind != Value::Kind::Map) {
    *error = path + ": expected a JSON object {\"PATH\": value, ...}";
    return false;
  }
  return Flatten(doc, "", path, overrides, error);
}

}  // namespace essaim
