// ARGoS's CLEDEquippedEntity (argos3/plugins/simulator/entities/led_equipped_entity.h): the
// LEDs of a box, a cylinder or a foot-bot. LEDs are added before the entity joins the space;
// AddToMedium names the <led> medium cameras see them through.
#pragma once
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
  CLEDEntity& GetLED(UInt32 un_index);
  void SetLEDColor(UInt32 un_index, const CColor& c_color);
  void SetAllLEDsColors(const CColor& c_color);
  void SetAllLEDsColors(const std::vector<CColor>& vec_colors);
  void AddToMedium(CLEDMedium& c_medium);
  /// ARGoS moves its LEDs with their body here; essaim's LEDs follow their body already.
  void Update() {}
  /// The medium's id, "" before AddToMedium.
  const std::string& GetMediumId() const { return m_strMedium; }

 private:
  TLEDEntityVector m_vecLEDs;  // owned
  std::string m_strMedium;
};

}  // namespace argos
