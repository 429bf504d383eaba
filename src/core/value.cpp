#include "core/value.h"

#include <limits>

namespace essaim {

Value Value::OfBool(bool b) {
  Value v;
  v.kind = Kind::Bool;
  v.boolean = b;
  return v;
}

Value Value::OfInteger(int64_t i) {
  Value v;
  v.kind = Kind::Integer;
  v.integer = i;
  return v;
}

Value Value::OfUnsigned(uint64_t u) {
  if (u <= static_cast<uint64_t>(std::numeric_limits<int64_t>::max())) return OfInteger(static_cast<int64_t>(u));
  Value v;
  v.kind = Kind::Unsigned;
  v.big_unsigned = u;
  return v;
}

Value Value::OfNumber(double d) {
  Value v;
  v.kind = Kind::Number;
  v.number = d;
  return v;
}

Value Value::OfString(std::string s) {
  Value v;
  v.kind = Kind::String;
  v.text = std::move(s);
  return v;
}

Value Value::EmptyList() {
  Value v;
  v.kind = Kind::List;
  return v;
}

Value Value::EmptyMap() {
  Value v;
  v.kind = Kind::Map;
  return v;
}

Value Value::OfStrings(const std::vector<std::string>& texts) {
  Value v = EmptyList();
  v.list.reserve(texts.size());
  for (const std::string& t : texts) v.list.push_back(OfString(t));
  return v;
}

Value Value::MapOf(std::initializer_list<std::pair<const char*, Value>> entries) {
  Value v = EmptyMap();
  v.map.reserve(entries.size());
  for (const auto& [key, value] : entries) v.map.emplace_back(key, value);
  return v;
}

const Value* Value::Find(const std::string& key) const {
  if (kind != Kind::Map) return nullptr;
  for (const auto& entry : map)
    if (entry.first == key) return &entry.second;
  return nullptr;
}

void Value::Set(const std::string& key, Value v) {
  for (auto& entry : map)
    if (entry.first == key) {
      entry.second = std::move(v);
      return;
    }
  map.emplace_back(key, std::move(v));
}

}  // namespace essaim
