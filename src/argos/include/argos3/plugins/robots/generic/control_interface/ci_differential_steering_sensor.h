// ARGoS's CCI_DifferentialSteeringSensor
// (argos3/plugins/robots/generic/control_interface/ci_differential_steering_sensor.h): the
// wheels' velocities (cm/s), the distance each covered in the last tick (cm) and the axis
// length (cm).
#pragma once
#include <argos3/core/control_interface/ci_sensor.h>

namespace argos {

class CCI_DifferentialSteeringSensor : public CCI_Sensor {
 public:
  struct SReading {
    Real VelocityLeftWheel;
    Real VelocityRightWheel;
    Real CoveredDistanceLeftWheel;
    Real CoveredDistanceRightWheel;
    Real WheelAxisLength;
    SReading()
        : VelocityLeftWheel(0.0),
          VelocityRightWheel(0.0),
          CoveredDistanceLeftWheel(0.0),
          CoveredDistanceRightWheel(0.0),
          WheelAxisLength(0.0) {}
    SReading(Real f_velocity_left_wheel, Real f_velocity_right_wheel, Real f_covered_distance_left_wheel,
             Real f_covered_distance_right_wheel, Real f_wheel_axis_length)
        : VelocityLeftWheel(f_velocity_left_wheel),
          VelocityRightWheel(f_velocity_right_wheel),
          CoveredDistanceLeftWheel(f_covered_distance_left_wheel),
          CoveredDistanceRightWheel(f_covered_distance_right_wheel),
          WheelAxisLength(f_wheel_axis_length) {}
  };

  CCI_DifferentialSteeringSensor() {}
  virtual ~CCI_DifferentialSteeringSensor() {}
  const SReading& GetReading() const { return m_sReading; }

 protected:
  SReading m_sReading;
};

}  // namespace argos
