// ARGoS's CCI_ColoredBlobOmnidirectionalCameraSensor
// (argos3/plugins/robots/generic/control_interface/ci_colored_blob_omnidirectional_camera_sensor.h):
// the LEDs the camera sees, each a blob with its colour, angle (rad) and distance (cm), and
// the number of updates taken since the camera was enabled or reset. Off until the controller
// calls Enable(); blobs show from the control step after it.
#pragma once
#include <argos3/core/control_interface/ci_sensor.h>
#include <argos3/core/utility/datatypes/color.h>
#include <argos3/core/utility/logging/argos_log.h>
#include <argos3/core/utility/math/angles.h>

#include <ostream>
#include <vector>

namespace argos {

class CCI_ColoredBlobOmnidirectionalCameraSensor : public CCI_Sensor {
 public:
  struct SBlob {
    CColor Color;
    CRadians Angle;
    Real Distance;
    SBlob() : Color(CColor::BLACK), Distance(0.0) {}
    SBlob(const CColor& c_color, const CRadians& c_angle, Real f_distance)
        : Color(c_color), Angle(c_angle), Distance(f_distance) {}
    friend std::ostream& operator<<(std::ostream& c_os, const SBlob& s_blob) {
      return c_os << "(Color = " << s_blob.Color << ","
                  << "Angle = " << ToDegrees(s_blob.Angle) << ","
                  << "Distance = " << s_blob.Distance << ")";
    }
  };
  /// The sensor owns the blobs; a pointer stays valid until the next update.
  typedef std::vector<SBlob*> TBlobList;
  struct SReadings {
    TBlobList BlobList;
    UInt64 Counter;
    SReadings() : Counter(0) {}
    friend std::ostream& operator<<(std::ostream& c_os, const SReadings& s_readings) {
      c_os << "Counter: " << s_readings.Counter << std::endl;
      for (size_t i = 0; i < s_readings.BlobList.size(); ++i)
        c_os << "Blob[" << i << "]: " << *s_readings.BlobList[i] << std::endl;
      return c_os;
    }
  };

  CCI_ColoredBlobOmnidirectionalCameraSensor() {}
  virtual ~CCI_ColoredBlobOmnidirectionalCameraSensor() {}
  const SReadings& GetReadings() const { return m_sReadings; }

 protected:
  SReadings m_sReadings;
};

}  // namespace argos
