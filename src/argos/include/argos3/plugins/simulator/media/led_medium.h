// ARGoS's CLEDMedium (argos3/plugins/simulator/media/led_medium.h): a <led> medium, what
// cameras see LEDs and lights through.
#pragma once
#include <argos3/core/simulator/medium/medium.h>
#include <argos3/plugins/simulator/entities/led_entity.h>

namespace argos {

class CLEDMedium : public CMedium {
 public:
  explicit CLEDMedium(const std::string& str_id) : CMedium(str_id) {}
};

}  // namespace argos
