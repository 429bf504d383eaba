#include "core/json.h"

namespace essaim {

std::string DumpJson(const Json& doc) {
  return doc.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

std::string DumpJsonLine(const Json& doc) {
  return doc.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

Json ToJson(const Value& value) {
  switch (value.kind) {
    case Value::Kind::Null:
      return Json();
    case Value::Kind::Bool:
      return Json(value.boolean);
    case Value::Kind::Integer:
      return Json(value.integer);
    case Value::Kind::Unsigned:
      return Json(value.big_unsigned);
    case Value::Kind::Number:
      return Json(value.number);
    case Value::Kind::String:
      return Json(value.text);
    case Value::Kind::List: {
      Json out = Json::array();
      auto& items = out.get_ref<Json::array_t&>();
      items.reserve(value.list.size());
      for (const Value& item : value.list) items.push_back(ToJson(item));
      return out;
    }
    case Value::Kind::Map: {
      Json out = Json::object();
      auto& entries = out.get_ref<Json::object_t&>();  // a vector of pairs, in order
      entries.reserve(value.map.size());
      for (const auto& [key, item] : value.map) entries.emplace_back(key, ToJson(item));  // keys unique: no lookup
      return out;
    }
  }
  return Json();
}

std::string ValueJsonText(const Value& value) { return DumpJson(ToJson(value)); }

std::string ValueJsonLine(const Value& value) { return DumpJsonLine(ToJson(value)); }

namespace {
Value NumberValue(const Json& doc) {
  if (doc.is_number_unsigned()) return Value::OfUnsigned(doc.get<uint64_t>());
  if (doc.is_number_integer()) return Value::OfInteger(doc.get<int64_t>());
  return Value::OfNumber(doc.get<double>());
}

Value FromJson(const Json& doc) {
  if (doc.is_boolean()) return Value::OfBool(doc.get<bool>());
  if (doc.is_number()) return NumberValue(doc);
  if (doc.is_string()) return Value::OfString(doc.get<std::string>());
  if (doc.is_array()) {
    Value out = Value::EmptyList();
    out.list.reserve(doc.size());
    for (const Json& item : doc) out.list.push_back(FromJson(item));
    return out;
  }
  if (doc.is_object()) {
    Value out = Value::EmptyMap();
    out.map.reserve(doc.size());
    for (const auto& [key, item] : doc.items()) out.map.emplace_back(key, FromJson(item));  // keys already unique
    return out;
  }
  return Value();
}
}  // namespace

bool ParseJson(const std::string& text, Json* out, std::string* error) {
  try {
    *out = Json::parse(text);
    return true;
  } catch (const nlohmann::json::parse_error& e) {
    // e.what() reads "[json.exception.parse_error.101] parse error at line 2, column 5: ..."
    std::string what = e.what();
    size_t at = what.find("at line");
    *error = "invalid JSON " + (at == std::string::npos ? what : what.substr(at));
    return false;
  }
}

bool ParseJsonValue(const std::string& text, Value* out, std::string* error) {
  Json doc;
  if (!ParseJson(text, &doc, error)) return false;
  *out = FromJson(doc);
  return true;
}

}  // namespace essaim
