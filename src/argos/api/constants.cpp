// The API's named values (CColor::RED, CRadians::PI, CVector3::Z...), defined once in the
// library as ARGoS defines them.
#include <argos3/core/utility/datatypes/color.h>
#include <argos3/core/utility/math/range.h>
#include <argos3/core/utility/math/vector3.h>

#include <sstream>
#include <utility>

namespace argos {

const CColor CColor::BLACK(0, 0, 0), CColor::WHITE(255, 255, 255), CColor::RED(255, 0, 0), CColor::GREEN(0, 255, 0),
    CColor::BLUE(0, 0, 255), CColor::MAGENTA(255, 0, 255), CColor::CYAN(0, 255, 255), CColor::YELLOW(255, 255, 0),
    CColor::ORANGE(255, 140, 0), CColor::BROWN(165, 42, 42), CColor::PURPLE(160, 32, 240), CColor::GRAY10(26, 26, 26),
    CColor::GRAY20(51, 51, 51), CColor::GRAY30(77, 77, 77), CColor::GRAY40(102, 102, 102),
    CColor::GRAY50(127, 127, 127), CColor::GRAY60(153, 153, 153), CColor::GRAY70(179, 179, 179),
    CColor::GRAY80(204, 204, 204), CColor::GRAY90(229, 229, 229);

void CColor::Set(const std::string& str_color) {
  static const std::pair<const char*, const CColor*> kNamed[] = {
      {"black", &BLACK},     {"white", &WHITE},   {"red", &RED},       {"green", &GREEN},   {"blue", &BLUE},
      {"magenta", &MAGENTA}, {"cyan", &CYAN},     {"yellow", &YELLOW}, {"orange", &ORANGE}, {"brown", &BROWN},
      {"purple", &PURPLE},   {"gray10", &GRAY10}, {"gray20", &GRAY20}, {"gray30", &GRAY30}, {"gray40", &GRAY40},
      {"gray50", &GRAY50},   {"gray60", &GRAY60}, {"gray70", &GRAY70}, {"gray80", &GRAY80}, {"gray90", &GRAY90}};
  for (const auto& named : kNamed)
    if (str_color == named.first) {
      *this = *named.second;
      return;
    }
  // "r,g,b,a": four numbers, each at most 255, as ARGoS reads a colour that is not a name.
  unsigned values[4];
  std::istringstream in(str_color);
  char comma = ',';
  for (int i = 0; i < 4; ++i) {
    if (i > 0) in >> comma;
    if (!(in >> values[i]) || comma != ',' || values[i] > 255)
      THROW_ARGOSEXCEPTION("Error while parsing color input string: \"" << str_color
                                                                        << "\" is not a colour name nor r,g,b,a");
  }
  Set(values[0], values[1], values[2], values[3]);
}

std::ostream& operator<<(std::ostream& os, const CColor& c) {
  return os << static_cast<int>(c.m_unRed) << "," << static_cast<int>(c.m_unGreen) << ","
            << static_cast<int>(c.m_unBlue) << "," << static_cast<int>(c.m_unAlpha);
}

const CRadians CRadians::PI(ARGOS_PI), CRadians::TWO_PI(2 * ARGOS_PI), CRadians::PI_OVER_TWO(ARGOS_PI / 2),
    CRadians::PI_OVER_THREE(ARGOS_PI / 3), CRadians::PI_OVER_FOUR(ARGOS_PI / 4), CRadians::PI_OVER_SIX(ARGOS_PI / 6),
    CRadians::ZERO(0);
const CRange<CRadians> CRadians::SIGNED_RANGE(-CRadians(ARGOS_PI), CRadians(ARGOS_PI));
const CRange<CRadians> CRadians::UNSIGNED_RANGE(CRadians(0), CRadians(2 * ARGOS_PI));

const CVector2 CVector2::ZERO(0, 0), CVector2::X(1, 0), CVector2::Y(0, 1);
const CVector3 CVector3::ZERO(0, 0, 0), CVector3::X(1, 0, 0), CVector3::Y(0, 1, 0), CVector3::Z(0, 0, 1);

}  // namespace argos
