// ARGoS's CPositionalEntity (argos3/core/simulator/entity/positional_entity.h): an entity
// with a position and an orientation. Lights are positional entities, and until ARGoS
// 3.0.0-beta30 bodies (CEmbodiedEntity) were too, so loop functions of that time read a
// body's pose with GetPosition() / GetOrientation().
//
// As in ARGoS, SetPosition / SetOrientation only write the pose this entity reports: a body
// in the space does not move (MoveEntity / MoveTo move it), and the physics overwrites what
// was set at its next update (the next tick) for a movable body, never for a static one. A
// light has no physics: setting its position moves it. Before AddEntity they set the pose
// the entity will be added with.
#pragma once
#include <argos3/core/simulator/entity/entity.h>
#include <argos3/core/utility/math/quaternion.h>
#include <argos3/core/utility/math/vector3.h>

#include <string>

namespace argos {

class CPositionalEntity : public CEntity {
 public:
  CPositionalEntity(CEntity* pc_parent, const std::string& str_id, const CVector3& c_position = CVector3(),
                    const CQuaternion& c_orientation = CQuaternion())
      : CEntity(pc_parent, str_id),
        m_cPosition(c_position),
        m_cInitPosition(c_position),
        m_cOrientation(c_orientation),
        m_cInitOrientation(c_orientation) {}
  std::string GetTypeDescription() const override { return "position"; }
  const CVector3& GetPosition() const;
  const CQuaternion& GetOrientation() const;
  void SetPosition(const CVector3& c_position);
  void SetOrientation(const CQuaternion& c_orientation);
  /// The pose it was made with (for an entity of the .argos file: where it stood at the start).
  const CVector3& GetInitPosition() const { return m_cInitPosition; }
  const CQuaternion& GetInitOrientation() const { return m_cInitOrientation; }
  void SetInitPosition(const CVector3& c_position) { m_cInitPosition = c_position; }
  void SetInitOrientation(const CQuaternion& c_orientation) { m_cInitOrientation = c_orientation; }

 protected:
  /// essaim's: a body that moved shows the world's pose again.
  void ForgetSetPose() { m_nPositionSetAt = m_nOrientationSetAt = -1; }

 private:
  mutable CVector3 m_cPosition;  // before the space: the pose it will be added with
  CVector3 m_cInitPosition;
  mutable CQuaternion m_cOrientation;
  CQuaternion m_cInitOrientation;
  // essaim's: the tick of the last SetPosition / SetOrientation on a body in the space
  // (-1: none); what was set hides the world's pose until the physics updates the body.
  SInt64 m_nPositionSetAt = -1;
  SInt64 m_nOrientationSetAt = -1;
};

}  // namespace argos
