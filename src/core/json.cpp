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
    case Value::Kind::Number:
      return Json(value.number);
    case Value::Kind::String:
      return Json(value.text);
    case Value::Kind::List: {
      Json out = Json::array();
      for (const Value& item : value.list) out.push_back(ToJson(item));
      return out;
    }
    case Value::Kind::Map: {
      Json out = Json::object();
      for (const auto& [key, item] : value.map) out[key] = ToJson(item);
      return out;
    }
  }
  return Json();
}

std::string ValueJsonText(const Value& value) { return DumpJson(ToJson(value)); }

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

}  // namespace essaim
