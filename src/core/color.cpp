#include "core/color.h"

#include <cstring>

#include "core/strings.h"

namespace essaim {

std::optional<Color> ParseColor(const std::string& text) {
  struct Named {
    const char* name;
    unsigned char r, g, b;
  };
  static const Named kNames[] = {
      {"black", 0, 0, 0},        {"white", 255, 255, 255},  {"red", 255, 0, 0},        {"green", 0, 255, 0},
      {"blue", 0, 0, 255},       {"magenta", 255, 0, 255},  {"cyan", 0, 255, 255},     {"yellow", 255, 255, 0},
      {"orange", 255, 140, 0},   {"brown", 165, 42, 42},    {"purple", 160, 32, 240},  {"gray10", 26, 26, 26},
      {"gray20", 51, 51, 51},    {"gray30", 77, 77, 77},    {"gray40", 102, 102, 102}, {"gray50", 127, 127, 127},
      {"gray60", 153, 153, 153}, {"gray70", 179, 179, 179}, {"gray80", 204, 204, 204}, {"gray90", 229, 229, 229},
  };
  std::string t = Trim(text);
  for (const Named& n : kNames)
    if (t == n.name) return Color{n.r, n.g, n.b, 255};
  std::vector<std::string> parts = Split(t, ',');
  if (parts.size() != 4) return std::nullopt;
  unsigned char v[4];
  for (int i = 0; i < 4; ++i) {
    auto x = ParseInt(parts[i]);
    if (!x || *x < 0 || *x > 255) return std::nullopt;
    v[i] = static_cast<unsigned char>(*x);
  }
  return Color{v[0], v[1], v[2], v[3]};
}

}  // namespace essaim
