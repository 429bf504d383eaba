// ARGoS's CFloorEntity (argos3/core/simulator/entity/floor_entity.h): the arena's floor.
// With <floor source="loop_functions">, SetChanged() has the floor drawn again from
// GetFloorColor before the robots next sense it.
#pragma once
#include <argos3/core/simulator/entity/entity.h>
#include <argos3/core/utility/datatypes/color.h>
#include <argos3/core/utility/math/vector2.h>
#include <argos3/core/utility/math/vector3.h>

namespace argos {

class CFloorEntity : public CEntity {
 public:
  CFloorEntity() : CEntity("floor") {}
  std::string GetTypeDescription() const override { return "floor"; }
  void SetChanged();
};

}  // namespace argos
