// ARGoS's CCylinderEntity (argos3/plugins/simulator/entities/cylinder_entity.h).
#pragma once
#include <argos3/core/simulator/entity/composable_entity.h>
#include <argos3/core/simulator/entity/embodied_entity.h>
#include <argos3/plugins/simulator/entities/led_equipped_entity.h>

namespace argos {

class CCylinderEntity : public CComposableEntity {
 public:
  CCylinderEntity(const std::string& str_id, const CVector3& c_position, const CQuaternion& c_orientation,
                  bool b_movable, Real f_radius, Real f_height, Real f_mass = 1.0)
      : CComposableEntity(str_id),
        m_cEmbodied(this, str_id + ".body", c_position, c_orientation, b_movable),
        m_cLEDs(this, str_id + ".leds"),
        m_fRadius(f_radius),
        m_fHeight(f_height),
        m_fMass(f_mass) {}
  std::string GetTypeDescription() const override { return "cylinder"; }
  CEmbodiedEntity& GetEmbodiedEntity() { return m_cEmbodied; }
  CLEDEquippedEntity& GetLEDEquippedEntity() { return m_cLEDs; }
  Real GetRadius() const { return m_fRadius; }
  Real GetHeight() const { return m_fHeight; }
  Real GetMass() const { return m_fMass; }

 private:
  CEmbodiedEntity m_cEmbodied;
  CLEDEquippedEntity m_cLEDs;
  Real m_fRadius, m_fHeight, m_fMass;
};

}  // namespace argos
