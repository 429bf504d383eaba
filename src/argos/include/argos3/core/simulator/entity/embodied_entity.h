// ARGoS's CEmbodiedEntity (argos3/core/simulator/entity/embodied_entity.h): an entity's
// body. Its origin anchor is the body's base centre and orientation, read from the physics.
// It is a CPositionalEntity, as it was in ARGoS until 3.0.0-beta30, so the loop functions
// of that time can read GetPosition() / GetOrientation() / GetInitPosition() of a body.
#pragma once
#include <argos3/core/simulator/entity/entity.h>
#include <argos3/core/simulator/entity/positional_entity.h>
#include <argos3/core/simulator/physics_engine/physics_engine.h>
#include <argos3/core/utility/math/quaternion.h>

#include <string>

namespace argos {

struct SAnchor {
  std::string Id;
  UInt32 Index = 0;
  CVector3 OffsetPosition;
  CQuaternion OffsetOrientation;
  CVector3 Position;
  CQuaternion Orientation;
  bool InUse = true;
};

class CEmbodiedEntity : public CPositionalEntity {
 public:
  CEmbodiedEntity(CEntity* pc_parent, const std::string& str_id, const CVector3& c_position = CVector3(),
                  const CQuaternion& c_orientation = CQuaternion(), bool b_movable = true);
  std::string GetTypeDescription() const override { return "body"; }
  /// The body's pose now (before the entity is in the space: the pose it will be added with).
  const SAnchor& GetOriginAnchor() const;
  bool IsMovable() const;
  /// Moves the body there unless it would overlap another body; `b_check_only`: only
  /// says whether it would fit. ARGoS's MoveTo.
  bool MoveTo(const CVector3& c_position, const CQuaternion& c_orientation, bool b_check_only = false,
              bool b_ignore_collisions = false);

 private:
  mutable SAnchor m_sOriginAnchor;
  bool m_bMovable;
};

}  // namespace argos
