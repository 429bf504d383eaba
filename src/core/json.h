// A small JSON value tree and its serializer: enough for summaries and metrics, with
// deterministic output (object keys keep insertion order; numbers shortest round-trip).
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace essaim {

class Json {
 public:
  enum class Type { Null, Bool, Int, Number, String, Array, Object };
  Json() = default;
  static Json Bool(bool b) { Json j; j.type_ = Type::Bool; j.bool_ = b; return j; }
  static Json Int(int64_t i) { Json j; j.type_ = Type::Int; j.int_ = i; return j; }
  static Json Number(double d) { Json j; j.type_ = Type::Number; j.num_ = d; return j; }
  static Json String(std::string s) { Json j; j.type_ = Type::String; j.str_ = std::move(s); return j; }
  static Json Array() { Json j; j.type_ = Type::Array; return j; }
  static Json Object() { Json j; j.type_ = Type::Object; return j; }

  Type type() const { return type_; }
  /// Arrays: append. Objects: set (replacing an existing key).
  Json& Push(Json v) { items_.emplace_back(std::string(), std::move(v)); return items_.back().second; }
  Json& Set(const std::string& key, Json v);
  const Json* Get(const std::string& key) const;
  const std::vector<std::pair<std::string, Json>>& Items() const { return items_; }
  bool AsBool() const { return bool_; }
  double AsNumber() const { return type_ == Type::Int ? static_cast<double>(int_) : num_; }
  int64_t AsInt() const { return int_; }
  const std::string& AsString() const { return str_; }

  /// Pretty-printed with 2-space indentation, newline-terminated.
  std::string Dump() const;

 private:
  void DumpTo(std::string* out, int indent) const;
  Type type_ = Type::Null;
  bool bool_ = false;
  int64_t int_ = 0;
  double num_ = 0;
  std::string str_;
  std::vector<std::pair<std::string, Json>> items_;
};

std::string JsonEscape(const std::string& s);

}  // namespace essaim
