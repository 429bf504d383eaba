#include "core/json.h"

#include <cmath>
#include <cstdio>

#include "core/strings.h"

namespace essaim {

Json& Json::Set(const std::string& key, Json v) {
  for (auto& kv : items_)
    if (kv.first == key) return kv.second = std::move(v);
  items_.emplace_back(key, std::move(v));
  return items_.back().second;
}

const Json* Json::Get(const std::string& key) const {
  for (const auto& kv : items_)
    if (kv.first == key) return &kv.second;
  return nullptr;
}

std::string JsonEscape(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  return out + "\"";
}

void Json::DumpTo(std::string* out, int indent) const {
  std::string pad(indent + 2, ' '), close(indent, ' ');
  switch (type_) {
    case Type::Null: *out += "null"; break;
    case Type::Bool: *out += bool_ ? "true" : "false"; break;
    case Type::Int: *out += std::to_string(int_); break;
    case Type::Number:
      // JSON has no inf/nan: write null rather than an invalid document.
      *out += std::isfinite(num_) ? FormatDouble(num_) : "null";
      break;
    case Type::String: *out += JsonEscape(str_); break;
    case Type::Array:
    case Type::Object: {
      bool obj = type_ == Type::Object;
      if (items_.empty()) {
        *out += obj ? "{}" : "[]";
        break;
      }
      // Short arrays of scalars stay on one line.
      bool flat = !obj && items_.size() <= 16;
      for (const auto& kv : items_) flat &= kv.second.type_ != Type::Array && kv.second.type_ != Type::Object;
      *out += obj ? "{" : "[";
      for (size_t i = 0; i < items_.size(); ++i) {
        *out += flat ? (i ? ", " : "") : (i ? ",\n" : "\n") + pad;
        if (obj) *out += JsonEscape(items_[i].first) + ": ";
        items_[i].second.DumpTo(out, indent + 2);
      }
      *out += flat ? "" : "\n" + close;
      *out += obj ? "}" : "]";
      break;
    }
  }
}

std::string Json::Dump() const {
  std::string out;
  DumpTo(&out, 0);
  return out + "\n";
}

}  // namespace essaim
