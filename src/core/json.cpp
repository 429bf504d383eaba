#include "core/json.h"

namespace essaim {

std::string DumpJson(const Json& doc) {
  return doc.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

std::string DumpJsonLine(const Json& doc) {
  return doc.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

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
