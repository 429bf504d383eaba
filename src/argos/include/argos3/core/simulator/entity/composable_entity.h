// ARGoS's CComposableEntity (argos3/core/simulator/entity/composable_entity.h): an entity
// made of components (a body, LEDs, a controller).
#pragma once
#include <argos3/core/simulator/entity/entity.h>
#include <argos3/core/simulator/space/space.h>

namespace argos {

class CComposableEntity : public CEntity {
 public:
  explicit CComposableEntity(const std::string& str_id) : CEntity(str_id) {}
  std::string GetTypeDescription() const override { return "composite"; }
};

}  // namespace argos
