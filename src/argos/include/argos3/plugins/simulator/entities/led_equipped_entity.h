// ARGoS's CLEDEquippedEntity (argos3/plugins/simulator/entities/led_equipped_entity.h): the
// LEDs of a box, a cylinder or a foot-bot. LEDs are added before the entity joins the space;
// AddToMedium names the <led> medium cameras see them through.
#pragma once
#include <argos3/core/simulator/entity/composable_entity.h>
#include <argos3/plugins/simulator/entities/led_entity.h>
#include <argos3/plugins/simulator/media/led_medium.h>

#include <memory>
#include <vector>

namespace argos {

class CLEDEquippedEntity : public CEntity {
 public:
  typedef std::vector<CLEDEntity*> TLEDEntityVector;
  CLEDEquippedEntity(CEntity* pc_parent, const std::string& str_id) : CEntity(pc_parent, str_id) {}
  ~CLEDEquippedEntity() override;
  std::string GetTypeDescription() const override { return "leds"; }
  /// An LED at `c_offset` from the body's origin; before the entity is added to the space.
  void AddLED(const CVector3& c_offset, const CColor& c_color = CColor::BLACK);
  const TLEDEntityVector& GetLEDs() const { return m_vecLEDs; }
  /// ARGoS's name for GetLEDs until 3.0.0-beta30.
  const CLEDEntity::TList& GetAllLEDs() const { return m_vecLEDs; }
  /// LED `un_idx`'s offset from the body's origin (GetLEDOffsetPosition until 3.0.0-beta30).
  const CVector3& GetLEDOffset(size_t un_idx) const { return GetLEDAt(un_idx).GetOffset(); }
  const CVector3& GetLEDOffsetPosition(size_t un_idx) const { return GetLEDOffset(un_idx); }
  CLEDEntity& GetLED(UInt32 un_index);
  void SetLEDColor(UInt32 un_index, const CColor& c_color);
  void SetAllLEDsColors(const CColor& c_color);
  void SetAllLEDsColors(const std::vector<CColor>& vec_colors);
  void AddToMedium(CLEDMedium& c_medium);
  /// ARGoS's name for AddToMedium since 3.0.0-beta49.
  void SetMedium(CLEDMedium& c_medium) { AddToMedium(c_medium); }
  /// ARGoS moves its LEDs with their body here; essaim's LEDs follow their body already.
  void Update() {}
  /// The medium's id, "" before AddToMedium.
  const std::string& GetMediumId() const { return m_strMedium; }

 private:
  const CLEDEntity& GetLEDAt(size_t un_idx) const {
    return const_cast<CLEDEquippedEntity*>(this)->GetLED(static_cast<UInt32>(un_idx));
  }
  TLEDEntityVector m_vecLEDs;  // owned
  std::string m_strMedium;
};

}  // namespace argos
