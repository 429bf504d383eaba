// ARGoS's CLEDEntity (argos3/plugins/simulator/entities/led_entity.h): one LED of a box, a
// cylinder or a foot-bot.
#pragma once
#include <argos3/core/simulator/entity/entity.h>
#include <argos3/core/simulator/entity/positional_entity.h>
#include <argos3/core/utility/datatypes/color.h>
#include <argos3/core/utility/math/vector3.h>

#include <vector>

namespace argos {

class CLEDEquippedEntity;

class CLEDEntity : public CEntity {
 public:
  typedef std::vector<CLEDEntity*> TList;
  CLEDEntity(CLEDEquippedEntity* pc_parent, UInt32 un_index, const CVector3& c_offset, const CColor& c_color);
  std::string GetTypeDescription() const override { return "led"; }
  /// The colour now (the world's once the entity is in the space).
  CColor GetColor() const;
  void SetColor(const CColor& c_color);
  const CVector3& GetOffset() const { return m_cOffset; }

 private:
  friend class CLEDEquippedEntity;
  CLEDEquippedEntity& m_cEquipped;
  UInt32 m_unIndex;
  CVector3 m_cOffset;
  CColor m_cColor;  // until the entity is in the space
};

}  // namespace argos
