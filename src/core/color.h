// ARGoS colour names and "r,g,b,a" strings.
#pragma once
#include <optional>
#include <string>

#include "core/math.h"

namespace essaim {

/// Named colour or exactly four 0..255 components "r,g,b,a".
std::optional<Color> ParseColor(const std::string& text);

}  // namespace essaim
