// ARGoS's CBoxEntity (argos3/plugins/simulator/entities/box_entity.h).
#pragma once
#include <argos3/core/simulator/entity/composable_entity.h>
#include <argos3/core/simulator/entity/embodied_entity.h>
#include <argos3/plugins/simulator/entities/led_equipped_entity.h>

namespace argos {

class CBoxEntity : public CComposableEntity {
 public:
  CBoxEntity(const std::string& str_id, const CVector3& c_position, const CQuaternion& c_orientation, bool b_movable,
             const CVector3& c_size, Real f_mass = 1.0)
      : CComposableEntity(str_id),
        m_cEmbodied(this, str_id + ".body", c_position, c_orientation, b_movable),
        m_cLEDs(this, str_id + ".leds"),
        m_cSize(c_size),
        m_fMass(f_mass) {}
  std::string GetTypeDescription() const override { return "box"; }
  CEmbodiedEntity& GetEmbodiedEntity() { return m_cEmbodied; }
  CLEDEquippedEntity& GetLEDEquippedEntity() { return m_cLEDs; }
  const CVector3& GetSize() const { return m_cSize; }
  Real GetMass() const { return m_fMass; }

 private:
  CEmbodiedEntity m_cEmbodied;
  CLEDEquippedEntity m_cLEDs;
  CVector3 m_cSize;
  Real m_fMass;
};

}  // namespace argos
