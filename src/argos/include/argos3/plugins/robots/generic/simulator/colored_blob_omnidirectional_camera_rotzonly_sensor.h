// ARGoS's CColoredBlobOmnidirectionalCameraRotZOnlySensor
// (argos3/plugins/robots/generic/simulator/colored_blob_omnidirectional_camera_rotzonly_sensor.h): the
// <colored_blob_omnidirectional_camera implementation="rot_z_only"> sensor a C++ controller's GetSensor returns.
// Disabled from the start: the robot's camera sees nothing until Enable(), so blobs show from the control step after
// it.
#pragma once
#include <argos3/core/simulator/sensor.h>
#include <argos3/core/simulator/space/space.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/plugins/robots/generic/control_interface/ci_colored_blob_omnidirectional_camera_sensor.h>

#include <vector>

namespace argos {

class CColoredBlobOmnidirectionalCameraRotZOnlySensor : public CCI_ColoredBlobOmnidirectionalCameraSensor,
                                                        public CSimulatedSensor {
 public:
  ~CColoredBlobOmnidirectionalCameraRotZOnlySensor() override;
  /// While disabled, nothing: the last readings stay, as ARGoS's.
  void Update() override;
  void Reset() override;
  void Enable() override;
  void Disable() override;

 private:
  std::vector<SBlob*> m_vecBlobs;  // every blob made so far, reused from tick to tick
};

}  // namespace argos
