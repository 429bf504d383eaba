// Inside the ARGoS API library: ARGoS entities to the world's specs and back. AddEntity
// turns a box, cylinder or light made with `new` into a world entity; a world entity seen
// for the first time gets a wrapper of its ARGoS class.
#pragma once
#include <argos3/core/simulator/entity/entity.h>
#include <argos3/core/utility/math/quaternion.h>

#include <memory>
#include <string>

#include "argos/argos_world.h"

namespace argos {

Real YawOf(const CQuaternion& c_orientation);
CQuaternion FromYaw(Real f_yaw);

/// Adds `c_entity` (a foot-bot, box, cylinder or light) to `world`; false with `error`.
bool AddToWorld(essaim::ArgosWorld& world, CEntity& c_entity, essaim::ArgosRef* ref, std::string* error);
/// A wrapper of world entity `ref`, bound to it.
std::unique_ptr<CEntity> MakeWrapper(essaim::ArgosWorld& world, const essaim::ArgosRef& ref);

}  // namespace argos
