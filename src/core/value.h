// A plain value tree: what a loop function's post_experiment() table or a controller's
// global holds (null, boolean, integer, number, string, list, map). Lua, sim and the Python
// module pass it around; output/ and core/json turn it into JSON text.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace essaim {

struct Value {
  enum class Kind : uint8_t { Null, Bool, Integer, Number, String, List, Map };
  Kind kind = Kind::Null;
  bool boolean = false;
  int64_t integer = 0;
  double number = 0;
  std::string text;
  std::vector<Value> list;
  std::vector<std::pair<std::string, Value>> map;  // insertion order; keys unique

  static Value OfBool(bool b);
  static Value OfInteger(int64_t i);
  static Value OfNumber(double d);
  static Value OfString(std::string s);
  static Value EmptyList();
  static Value EmptyMap();

  bool IsNull() const { return kind == Kind::Null; }
  /// map[key] = v: an existing key keeps its place and takes the new value.
  void Set(const std::string& key, Value v);
};

/// The value as JSON text, pretty-printed as DumpJson writes it (core/json.cpp: the JSON
/// adapter), for callers that want the text and not the JSON library.
std::string ValueJsonText(const Value& value);

}  // namespace essaim
