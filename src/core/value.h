// A plain value tree: what a loop function's post_experiment() table or a controller's
// global holds (null, boolean, integer, number, string, list, map), or a JSON document. Lua,
// sim, output, serve and the Python module pass it around; core/value_json.h turns it into
// JSON text and back.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace essaim {

struct Value {
  /// Unsigned: an integer past int64's range (a 64-bit seed), which Lua never makes.
  enum class Kind : uint8_t { Null, Bool, Integer, Unsigned, Number, String, List, Map };
  Kind kind = Kind::Null;
  bool boolean = false;
  int64_t integer = 0;
  uint64_t big_unsigned = 0;  // Kind::Unsigned only
  double number = 0;
  std::string text;
  std::vector<Value> list;
  std::vector<std::pair<std::string, Value>> map;  // insertion order; keys unique

  static Value OfBool(bool b);
  static Value OfInteger(int64_t i);
  /// Integer when it fits int64, else Unsigned.
  static Value OfUnsigned(uint64_t u);
  static Value OfNumber(double d);
  static Value OfString(std::string s);
  static Value EmptyList();
  static Value EmptyMap();
  /// A list of strings.
  static Value OfStrings(const std::vector<std::string>& texts);
  /// A map of these entries, in this order (keys unique).
  static Value MapOf(std::initializer_list<std::pair<const char*, Value>> entries);

  bool IsNull() const { return kind == Kind::Null; }
  /// A map's value under `key`; null when this is not a map or has no such key.
  const Value* Find(const std::string& key) const;
  /// map[key] = v: an existing key keeps its place and takes the new value.
  void Set(const std::string& key, Value v);
};

}  // namespace essaim
