#include "core/value.h"

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

void Value::Set(const std::string& key, Value v) {
  for (auto& entry : map)
    if (entry.first == key) {
      entry.second = std::move(v);
      return;
    }
  map.emplace_back(key, std::move(v));
}

}  // namespace essaim
