// ARGoS's CColor (argos3/core/utility/datatypes/color.h): RGBA, 0-255 each.
#pragma once
#include <argos3/core/utility/datatypes/datatypes.h>
#include <argos3/core/utility/string_utilities.h>

#include <istream>
#include <ostream>
#include <string>

namespace argos {

class CColor {
 public:
  CColor() = default;
  CColor(UInt8 un_red, UInt8 un_green, UInt8 un_blue, UInt8 un_alpha = 255)
      : m_unRed(un_red), m_unGreen(un_green), m_unBlue(un_blue), m_unAlpha(un_alpha) {}
  UInt8 GetRed() const { return m_unRed; }
  UInt8 GetGreen() const { return m_unGreen; }
  UInt8 GetBlue() const { return m_unBlue; }
  UInt8 GetAlpha() const { return m_unAlpha; }
  void SetRed(UInt8 u) { m_unRed = u; }
  void SetGreen(UInt8 u) { m_unGreen = u; }
  void SetBlue(UInt8 u) { m_unBlue = u; }
  void SetAlpha(UInt8 u) { m_unAlpha = u; }
  void Set(UInt8 r, UInt8 g, UInt8 b, UInt8 a = 255) { m_unRed = r, m_unGreen = g, m_unBlue = b, m_unAlpha = a; }
  /// A name ("red", "gray50": ARGoS's constants in lower case) or "r,g,b,a"; throws otherwise.
  void Set(const std::string& str_color);
  /// The four channels as one number, red in the low byte (ARGoS's bytes read as a
  /// little-endian UInt32): a key for maps of colours.
  operator UInt32() {
    return static_cast<UInt32>(m_unRed) | static_cast<UInt32>(m_unGreen) << 8 | static_cast<UInt32>(m_unBlue) << 16 |
           static_cast<UInt32>(m_unAlpha) << 24;
  }
  /// 0.299 R + 0.587 G + 0.114 B, as ARGoS's ground sensors see a colour.
  Real ToGrayScale() const { return 0.299 * m_unRed + 0.587 * m_unGreen + 0.114 * m_unBlue; }
  bool operator==(const CColor& c) const {
    return m_unRed == c.m_unRed && m_unGreen == c.m_unGreen && m_unBlue == c.m_unBlue && m_unAlpha == c.m_unAlpha;
  }
  bool operator!=(const CColor& c) const { return !(*this == c); }
  friend std::ostream& operator<<(std::ostream& os, const CColor& c);
  friend std::istream& operator>>(std::istream& is, CColor& c) {
    std::string strColor;
    is >> strColor;
    c.Set(strColor);
    return is;
  }

  static const CColor BLACK, WHITE, RED, GREEN, BLUE, MAGENTA, CYAN, YELLOW, ORANGE, BROWN, PURPLE, GRAY10, GRAY20,
      GRAY30, GRAY40, GRAY50, GRAY60, GRAY70, GRAY80, GRAY90;

 private:
  UInt8 m_unRed = 0, m_unGreen = 0, m_unBlue = 0, m_unAlpha = 255;
};

}  // namespace argos
