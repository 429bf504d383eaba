// ARGoS's CLightEntity (argos3/plugins/simulator/entities/light_entity.h): a light that
// light sensors measure and, through a <led> medium, cameras see.
#pragma once
#include <argos3/core/simulator/entity/entity.h>
#include <argos3/core/utility/datatypes/color.h>
#include <argos3/core/utility/math/vector3.h>
#include <argos3/plugins/simulator/media/led_medium.h>

namespace argos {

class CLightEntity : public CEntity {
 public:
  CLightEntity(const std::string& str_id, const CVector3& c_position, const CColor& c_color, Real f_intensity)
      : CEntity(str_id), m_cPosition(c_position), m_cColor(c_color), m_fIntensity(f_intensity) {}
  std::string GetTypeDescription() const override { return "light"; }
  CVector3 GetPosition() const;
  void SetPosition(const CVector3& c_position);
  CColor GetColor() const;
  void SetColor(const CColor& c_color);
  Real GetIntensity() const;
  void SetIntensity(Real f_intensity);
  void AddToMedium(CLEDMedium& c_medium);
  const std::string& GetMediumId() const { return m_strMedium; }

 private:
  CVector3 m_cPosition;  // until the light is in the space
  CColor m_cColor;
  Real m_fIntensity;
  std::string m_strMedium;
};

}  // namespace argos
