// ARGoS's CLightEntity (argos3/plugins/simulator/entities/light_entity.h): a light that
// light sensors measure and, through a <led> medium, cameras see.
#pragma once
#include <argos3/core/simulator/entity/positional_entity.h>
#include <argos3/plugins/simulator/entities/led_equipped_entity.h>
#include <argos3/plugins/simulator/media/led_medium.h>

namespace argos {

/// A positional entity, as ARGoS's: GetPosition / SetPosition (which moves it) come from there.
class CLightEntity : public CPositionalEntity {
 public:
  CLightEntity(const std::string& str_id, const CVector3& c_position, const CColor& c_color, Real f_intensity)
      : CPositionalEntity(nullptr, str_id, c_position), m_cColor(c_color), m_fIntensity(f_intensity) {}
  std::string GetTypeDescription() const override { return "light"; }
  CColor GetColor() const;
  void SetColor(const CColor& c_color);
  Real GetIntensity() const;
  void SetIntensity(Real f_intensity);
  void AddToMedium(CLEDMedium& c_medium);
  const std::string& GetMediumId() const { return m_strMedium; }

 private:
  CColor m_cColor;
  Real m_fIntensity;
  std::string m_strMedium;
};

}  // namespace argos
