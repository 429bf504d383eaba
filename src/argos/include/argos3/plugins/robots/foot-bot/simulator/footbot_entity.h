// ARGoS's CFootBotEntity (argos3/plugins/robots/foot-bot/simulator/footbot_entity.h): a
// foot-bot of the .argos file, with its body, LEDs and Lua controller.
#pragma once
#include <argos3/core/simulator/entity/composable_entity.h>
#include <argos3/core/simulator/entity/controllable_entity.h>
#include <argos3/core/simulator/entity/embodied_entity.h>
#include <argos3/plugins/simulator/entities/led_equipped_entity.h>

namespace argos {

class CFootBotEntity : public CComposableEntity {
 public:
  /// ARGoS's constructor. AddEntity puts the robot in the space and makes its controller
  /// (`str_controller_id`, a <lua_controller> of the .argos file), which runs its script and
  /// init() then. The battery model and the perspective camera are not modelled: a robot
  /// made here has no <battery> (never depletes) and no perspective camera.
  CFootBotEntity(const std::string& str_id, const std::string& str_controller_id,
                 const CVector3& c_position = CVector3(), const CQuaternion& c_orientation = CQuaternion(),
                 Real f_rab_range = 3.0, size_t un_rab_data_size = 10, const std::string& str_bat_model = "",
                 const CRadians& c_omnicam_aperture = CRadians(1.2740903539558606), bool b_perspcam_front = true,
                 const CRadians& c_perspcam_aperture = CRadians(0.5235987755982988),
                 Real f_perspcam_focal_length = 0.035, Real f_perspcam_range = 2.0)
      : CComposableEntity(str_id),
        m_cEmbodied(this, str_id + ".body", c_position, c_orientation, true),
        m_cControllable(this, str_id + ".controller", str_controller_id),
        m_cLEDs(this, str_id + ".leds"),
        m_strControllerId(str_controller_id),
        m_fRabRange(f_rab_range),
        m_unRabDataSize(un_rab_data_size),
        m_cOmnicamAperture(c_omnicam_aperture) {
    (void)str_bat_model, (void)b_perspcam_front, (void)c_perspcam_aperture, (void)f_perspcam_focal_length;
    (void)f_perspcam_range;
  }
  /// ARGoS 3.0.0-beta35 to beta48's: no battery model, the omnidirectional camera's aperture
  /// after the RAB data size.
  CFootBotEntity(const std::string& str_id, const std::string& str_controller_id, const CVector3& c_position,
                 const CQuaternion& c_orientation, Real f_rab_range, size_t un_rab_data_size,
                 const CRadians& c_omnicam_aperture, bool b_perspcam_front = true,
                 const CRadians& c_perspcam_aperture = CRadians(0.5235987755982988),
                 Real f_perspcam_focal_length = 0.035, Real f_perspcam_range = 2.0)
      : CFootBotEntity(str_id, str_controller_id, c_position, c_orientation, f_rab_range, un_rab_data_size, "",
                       c_omnicam_aperture, b_perspcam_front, c_perspcam_aperture, f_perspcam_focal_length,
                       f_perspcam_range) {}
  /// ARGoS 3.0.0-beta18 to beta34's: no RAB data size (10 bytes), the camera's aperture last.
  CFootBotEntity(const std::string& str_id, const std::string& str_controller_id, const CVector3& c_position,
                 const CQuaternion& c_orientation, Real f_rab_range, const CRadians& c_aperture)
      : CFootBotEntity(str_id, str_controller_id, c_position, c_orientation, f_rab_range, 10, "", c_aperture) {}
  std::string GetTypeDescription() const override { return "foot-bot"; }
  CEmbodiedEntity& GetEmbodiedEntity() { return m_cEmbodied; }
  CControllableEntity& GetControllableEntity() { return m_cControllable; }
  /// Its 13 LEDs (12 in the ring, 1 beacon), as its LED actuator last set them.
  CLEDEquippedEntity& GetLEDEquippedEntity() { return m_cLEDs; }

 private:
  CEmbodiedEntity m_cEmbodied;
  CControllableEntity m_cControllable;
  CLEDEquippedEntity m_cLEDs;
  friend struct SEntityBinding;  // essaim's: AddEntity reads the constructor's arguments
  std::string m_strControllerId;
  Real m_fRabRange;
  size_t m_unRabDataSize;
  CRadians m_cOmnicamAperture;
};

}  // namespace argos
