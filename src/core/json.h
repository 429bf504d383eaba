// JSON through nlohmann/json: the one adapter for it. Documents are ordered_json (objects
// keep insertion order); numbers are written shortest round-trip; NaN and infinities, which
// JSON cannot hold, are written as null. Included only in core: the layers above use
// core/value_json.h, which never names the library.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "core/value_json.h"

namespace essaim {

/// A JSON document; objects keep insertion order, so output is deterministic.
using Json = nlohmann::ordered_json;

/// Pretty-printed with 2-space indentation, newline-terminated. Strings are escaped
/// (control characters and NUL as \uXXXX); invalid UTF-8 is replaced, never an error.
std::string DumpJson(const Json& doc);
/// On one line, no indentation, no trailing newline (a frame for a live page, an API answer).
std::string DumpJsonLine(const Json& doc);
/// False with "line L, column C: ..." in `error` when `text` is not one JSON document.
bool ParseJson(const std::string& text, Json* out, std::string* error);
/// A plain value tree as a document: maps keep their order, lists stay lists.
Json ToJson(const Value& value);

}  // namespace essaim
