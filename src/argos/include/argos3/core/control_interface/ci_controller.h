// ARGoS's CCI_Controller (argos3/core/control_interface/ci_controller.h): a robot's C++
// controller, built into a library named by its .argos element
// (<footbot_diffusion_controller id library>) and registered with REGISTER_CONTROLLER. Its
// sensors and actuators are the objects made for the element's <sensors> and <actuators>
// children. Robots running a Lua controller show a CLuaController (lua_controller.h).
#pragma once
#include <argos3/core/control_interface/ci_actuator.h>
#include <argos3/core/control_interface/ci_sensor.h>
#include <argos3/core/utility/configuration/argos_configuration.h>  // ARGoS: through base_configurable_resource.h
#include <argos3/core/utility/configuration/argos_exception.h>
#include <argos3/core/utility/datatypes/datatypes.h>

#include <map>
#include <string>
#include <typeinfo>

/// The version of this API a library is built for; a library built for another one is
/// refused when it is loaded.
#define ARGOS_ESSAIM_API_VERSION 4

namespace argos {

class CCI_Controller {
 public:
  virtual ~CCI_Controller() {}
  virtual void Init(TConfigurationNode& t_node) { (void)t_node; }
  virtual void ControlStep() {}
  virtual void Reset() {}
  virtual void Destroy() {}

  /// The robot's id (set after the constructor, before Init, as ARGoS's).
  const std::string& GetId() const { return m_strId; }
  void SetId(const std::string& str_id) { m_strId = str_id; }

  /// The actuator declared as `str_actuator_type`, as an ACTUATOR_IMPL; throws when the
  /// .argos element does not declare it, or declares an implementation of another class.
  template <typename ACTUATOR_IMPL>
  ACTUATOR_IMPL* GetActuator(const std::string& str_actuator_type) {
    auto it = m_mapActuators.find(str_actuator_type);
    if (it == m_mapActuators.end()) ThrowUnknownDevice(false, str_actuator_type);
    ACTUATOR_IMPL* pcActuator = dynamic_cast<ACTUATOR_IMPL*>(it->second);
    if (!pcActuator) ThrowBadCast(false, str_actuator_type, typeid(ACTUATOR_IMPL).name(), typeid(*it->second).name());
    return pcActuator;
  }
  template <typename SENSOR_IMPL>
  SENSOR_IMPL* GetSensor(const std::string& str_sensor_type) {
    auto it = m_mapSensors.find(str_sensor_type);
    if (it == m_mapSensors.end()) ThrowUnknownDevice(true, str_sensor_type);
    SENSOR_IMPL* pcSensor = dynamic_cast<SENSOR_IMPL*>(it->second);
    if (!pcSensor) ThrowBadCast(true, str_sensor_type, typeid(SENSOR_IMPL).name(), typeid(*it->second).name());
    return pcSensor;
  }
  bool HasActuator(const std::string& str_actuator_type) const { return m_mapActuators.count(str_actuator_type) > 0; }
  bool HasSensor(const std::string& str_sensor_type) const { return m_mapSensors.count(str_sensor_type) > 0; }
  CCI_Actuator::TMap& GetAllActuators() { return m_mapActuators; }
  CCI_Sensor::TMap& GetAllSensors() { return m_mapSensors; }
  void AddActuator(const std::string& str_actuator_type, CCI_Actuator* pc_actuator) {
    m_mapActuators[str_actuator_type] = pc_actuator;
  }
  void AddSensor(const std::string& str_sensor_type, CCI_Sensor* pc_sensor) {
    m_mapSensors[str_sensor_type] = pc_sensor;
  }

 protected:
  CCI_Actuator::TMap m_mapActuators;
  CCI_Sensor::TMap m_mapSensors;
  std::string m_strId;

 private:
  // Out of line (the library): the message names the controller's .argos element too.
  [[noreturn]] static void ThrowUnknownDevice(bool b_sensor, const std::string& str_type);
  [[noreturn]] static void ThrowBadCast(bool b_sensor, const std::string& str_type, const char* str_wanted,
                                        const char* str_made);
};

typedef CCI_Controller* (*TControllerCreator)();
/// Called by REGISTER_CONTROLLER when the library is loaded.
bool RegisterController(const char* str_label, TControllerCreator pf_creator, int n_api_version);

}  // namespace argos

#define ARGOS_ESSAIM_CONCAT2(a, b) a##b
#define ARGOS_ESSAIM_CONCAT(a, b) ARGOS_ESSAIM_CONCAT2(a, b)
/// Makes class CLASSNAME the controller of the .argos elements whose tag is LABEL.
#define REGISTER_CONTROLLER(CLASSNAME, LABEL)                                                         \
  namespace {                                                                                         \
  const bool ARGOS_ESSAIM_CONCAT(argos_controller_registered_, __LINE__) = argos::RegisterController( \
      LABEL, []() -> argos::CCI_Controller* { return new CLASSNAME; }, ARGOS_ESSAIM_API_VERSION);     \
  }
