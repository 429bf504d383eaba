// ARGoS's ToString and FromString (argos3/core/utility/string_utilities.h).
#pragma once
#include <argos3/core/utility/configuration/argos_exception.h>
#include <argos3/core/utility/datatypes/datatypes.h>

#include <sstream>
#include <string>

namespace argos {

template <typename T>
std::string ToString(const T& t_value) {
  std::ostringstream stream;
  stream << t_value;
  return stream.str();
}

template <typename T>
T FromString(const std::string& str_value) {
  std::istringstream stream(str_value);
  T t_value{};
  stream >> t_value;
  if (stream.fail()) THROW_ARGOSEXCEPTION("cannot read '" << str_value << "'");
  return t_value;
}

}  // namespace argos
