// A value tree as JSON text and back, for code that wants the text and not the JSON library
// (core/json.cpp, the one adapter for it, does both: the text is DumpJson's and
// DumpJsonLine's, byte for byte).
#pragma once
#include <string>

#include "core/value.h"

namespace essaim {

/// Pretty-printed with 2-space indentation, newline-terminated; maps keep their order.
std::string ValueJsonText(const Value& value);
/// On one line, no indentation, no trailing newline (a frame for a live page, an API answer).
std::string ValueJsonLine(const Value& value);
/// `text` as a value tree: integers stay integers (Integer, or Unsigned past int64's range),
/// objects become maps in the text's order (a repeated key keeps its first place and its last
/// value). False with ParseJson's "invalid JSON at line L, column C: ..." in `error`.
bool ParseJsonValue(const std::string& text, Value* out, std::string* error);

}  // namespace essaim
