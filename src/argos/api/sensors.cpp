// The sensors a C++ controller reads: ARGoS's control-interface layouts (their constructors'
// sizes, angles and offsets are ARGoS's), filled each tick from the robot's readings
// (ArgosRobotIo). Once sized, an update allocates nothing: the readings' vectors, the
// camera's blobs and the packets' data buffers are reused.
#include <argos3/plugins/robots/foot-bot/simulator/footbot_base_ground_rotzonly_sensor.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_distance_scanner_rotzonly_sensor.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_light_rotzonly_sensor.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_motor_ground_rotzonly_sensor.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_proximity_default_sensor.h>
#include <argos3/plugins/robots/foot-bot/simulator/footbot_turret_encoder_default_sensor.h>
#include <argos3/plugins/robots/generic/simulator/battery_default_sensor.h>
#include <argos3/plugins/robots/generic/simulator/colored_blob_omnidirectional_camera_rotzonly_sensor.h>
#include <argos3/plugins/robots/generic/simulator/differential_steering_default_sensor.h>
#include <argos3/plugins/robots/generic/simulator/positioning_default_sensor.h>
#include <argos3/plugins/robots/generic/simulator/range_and_bearing_medium_sensor.h>

#include "argos/argos_robot_io.h"

namespace argos {

namespace {
// The foot-bot's ring of 24 proximity and light sensors: the first at half a spacing.
CRadians RingAngle(size_t i) {
  const Real fSpacing = ARGOS_PI / 12;
  return CRadians(fSpacing / 2 + fSpacing * static_cast<Real>(i)).SignedNormalize();
}

template <typename TReadings>
void FillRing(TReadings& t_readings, const double* pf_values, const double* pf_angles) {
  for (size_t i = 0; i < t_readings.size(); ++i) {
    t_readings[i].Value = pf_values[i];
    t_readings[i].Angle = CRadians(pf_angles[i]);
  }
}

template <typename TReadings>
void FillGround(TReadings& t_readings, const double* pf_values, const double (*pf_offsets)[2]) {
  for (size_t i = 0; i < t_readings.size(); ++i) {
    t_readings[i].Value = pf_values[i];
    t_readings[i].Offset.Set(pf_offsets[i][0], pf_offsets[i][1]);
  }
}

template <typename TReadings>
void ZeroValues(TReadings& t_readings) {
  for (auto& sReading : t_readings) sReading.Value = 0;
}

template <typename TReading>
std::ostream& WriteValues(std::ostream& c_os, const std::vector<TReading>& t_readings) {
  for (size_t i = 0; i < t_readings.size(); ++i) c_os << (i ? " " : "") << "{ " << t_readings[i].Value << " }";
  if (!t_readings.empty()) c_os << std::endl;
  return c_os;
}
}  // namespace

CCI_FootBotProximitySensor::CCI_FootBotProximitySensor() : m_tReadings(24) {
  for (size_t i = 0; i < m_tReadings.size(); ++i) m_tReadings[i].Angle = RingAngle(i);
}
CCI_FootBotLightSensor::CCI_FootBotLightSensor() : m_tReadings(24) {
  for (size_t i = 0; i < m_tReadings.size(); ++i) m_tReadings[i].Angle = RingAngle(i);
}
// ARGoS's offsets, cm: the 4 motor sensors beside the wheels, the 8 base ones on a ring.
CCI_FootBotMotorGroundSensor::CCI_FootBotMotorGroundSensor() : m_tReadings(4) {
  const Real kOffsets[4][2] = {{6.3, 1.16}, {-6.3, 1.16}, {-6.3, -1.16}, {6.3, -1.16}};
  for (size_t i = 0; i < 4; ++i) m_tReadings[i].Offset.Set(kOffsets[i][0], kOffsets[i][1]);
}
CCI_FootBotBaseGroundSensor::CCI_FootBotBaseGroundSensor() : m_tReadings(8) {
  const Real kOffsets[8][2] = {{8.0, 0.0},  {4.2, 6.5},   {0.0, 8.0},  {-4.2, 6.5},
                               {-8.0, 0.0}, {-4.2, -6.5}, {0.0, -8.0}, {4.2, -6.5}};
  for (size_t i = 0; i < 8; ++i) m_tReadings[i].Offset.Set(kOffsets[i][0], kOffsets[i][1]);
}
const CRange<CRadians> CCI_FootBotTurretEncoderSensor::ANGULAR_RANGE(CRadians(-ARGOS_PI), CRadians(ARGOS_PI));

std::ostream& operator<<(std::ostream& c_os, const CCI_FootBotProximitySensor::SReading& s_reading) {
  return c_os << "Value=<" << s_reading.Value << ">, Angle=<" << s_reading.Angle << ">";
}
std::ostream& operator<<(std::ostream& c_os, const CCI_FootBotProximitySensor::TReadings& t_readings) {
  return WriteValues(c_os, t_readings);
}
std::ostream& operator<<(std::ostream& c_os, const CCI_FootBotLightSensor::SReading& s_reading) {
  return c_os << "Value=<" << s_reading.Value << ">, Angle=<" << s_reading.Angle << ">";
}
std::ostream& operator<<(std::ostream& c_os, const CCI_FootBotLightSensor::TReadings& t_readings) {
  return WriteValues(c_os, t_readings);
}
std::ostream& operator<<(std::ostream& c_os, const CCI_FootBotMotorGroundSensor::SReading& s_reading) {
  return c_os << "Value=<" << s_reading.Value << ">, Offset=<" << s_reading.Offset << ">";
}
std::ostream& operator<<(std::ostream& c_os, const CCI_FootBotMotorGroundSensor::TReadings& t_readings) {
  return WriteValues(c_os, t_readings);
}
std::ostream& operator<<(std::ostream& c_os, const CCI_FootBotBaseGroundSensor::SReading& s_reading) {
  return c_os << "Value=<" << s_reading.Value << ">, Offset=<" << s_reading.Offset << ">";
}
std::ostream& operator<<(std::ostream& c_os, const CCI_FootBotBaseGroundSensor::TReadings& t_readings) {
  return WriteValues(c_os, t_readings);
}

// ---- foot-bot sensors

void CFootBotProximityDefaultSensor::Update() {
  FillRing(m_tReadings, m_pcRobotIo->Proximity(), m_pcRobotIo->ProximityAngles());
}

void CFootBotLightRotZOnlySensor::Update() {
  if (IsDisabled()) return;
  FillRing(m_tReadings, m_pcRobotIo->Light(), m_pcRobotIo->ProximityAngles());
}
void CFootBotLightRotZOnlySensor::Reset() { ZeroValues(m_tReadings); }

void CFootBotMotorGroundRotZOnlySensor::Update() {
  if (IsDisabled()) return;
  FillGround(m_tReadings, m_pcRobotIo->MotorGround(), m_pcRobotIo->MotorGroundOffsets());
}
void CFootBotMotorGroundRotZOnlySensor::Reset() { ZeroValues(m_tReadings); }

void CFootBotBaseGroundRotZOnlySensor::Update() {
  if (IsDisabled()) return;
  FillGround(m_tReadings, m_pcRobotIo->BaseGround(), m_pcRobotIo->BaseGroundOffsets());
}
void CFootBotBaseGroundRotZOnlySensor::Reset() { ZeroValues(m_tReadings); }

// The maps are filled again each tick, as ARGoS's, with their nodes taken out and put back
// rather than freed and allocated.
void CFootBotDistanceScannerRotZOnlySensor::Recycle(TReadingsMap& t_map) {
  while (!t_map.empty()) m_vecNodes.push_back(t_map.extract(t_map.begin()));
}
void CFootBotDistanceScannerRotZOnlySensor::Put(TReadingsMap& t_map, const CRadians& c_angle, Real f_distance) {
  if (m_vecNodes.empty()) {
    t_map[c_angle] = f_distance;
    return;
  }
  TReadingsMap::node_type tNode = std::move(m_vecNodes.back());
  m_vecNodes.pop_back();
  tNode.key() = c_angle;
  tNode.mapped() = f_distance;
  auto tInserted = t_map.insert(std::move(tNode));
  if (tInserted.inserted) return;
  tInserted.position->second = f_distance;  // an angle seen twice: the last reading, as ARGoS's
  m_vecNodes.push_back(std::move(tInserted.node));
}
void CFootBotDistanceScannerRotZOnlySensor::Update() {
  if (IsDisabled()) return;
  Reset();
  for (bool bShort : {true, false}) {
    TReadingsMap& tMap = bShort ? m_tShortReadingsMap : m_tLongReadingsMap;
    for (int k = 0; k < m_pcRobotIo->ScanCount(bShort); ++k) {
      const essaim::ArgosScan sScan = m_pcRobotIo->Scan(bShort, k);
      Put(tMap, CRadians(sScan.angle), sScan.distance);
      Put(m_tReadingsMap, CRadians(sScan.angle), sScan.distance);
    }
  }
}
void CFootBotDistanceScannerRotZOnlySensor::Reset() {
  Recycle(m_tReadingsMap);
  Recycle(m_tShortReadingsMap);
  Recycle(m_tLongReadingsMap);
}

void CFootBotTurretEncoderDefaultSensor::Update() {
  if (IsDisabled()) return;
  m_cRotation = CRadians(m_pcRobotIo->TurretRotation());
}
void CFootBotTurretEncoderDefaultSensor::Reset() { m_cRotation = CRadians::ZERO; }

// ---- generic sensors

void CDifferentialSteeringDefaultSensor::Update() {
  if (IsDisabled()) return;
  double fVelocity[2], fDistance[2], fAxis = 0;
  m_pcRobotIo->WheelReading(fVelocity, fDistance, &fAxis);
  m_sReading = SReading(fVelocity[0], fVelocity[1], fDistance[0], fDistance[1], fAxis);
}
void CDifferentialSteeringDefaultSensor::Reset() { m_sReading = SReading(0, 0, 0, 0, m_sReading.WheelAxisLength); }

void CPositioningDefaultSensor::Update() {
  if (IsDisabled()) return;
  double fPosition[3], fQuaternion[4];
  m_pcRobotIo->Positioning(fPosition, fQuaternion);
  m_sReading.Position.Set(fPosition[0], fPosition[1], fPosition[2]);
  m_sReading.Orientation = CQuaternion(fQuaternion[0], fQuaternion[1], fQuaternion[2], fQuaternion[3]);
}
// ARGoS's reads the robot's pose again; essaim's next update does.
void CPositioningDefaultSensor::Reset() {}

void CBatteryDefaultSensor::Update() {
  if (IsDisabled()) return;
  m_pcRobotIo->Battery(&m_sReading.AvailableCharge, &m_sReading.TimeLeft);
}
void CBatteryDefaultSensor::Reset() { m_sReading = SReading(); }

// Packets no longer needed go to the spare list with their data buffers, and come back
// from it first, so that a steady number of neighbours costs no allocation.
void CRangeAndBearingMediumSensor::Update() {
  if (IsDisabled()) return;
  const size_t unCount = static_cast<size_t>(m_pcRobotIo->RabCount());
  while (m_tReadings.size() > unCount) {
    m_tSpare.push_back(std::move(m_tReadings.back()));
    m_tReadings.pop_back();
  }
  while (m_tReadings.size() < unCount) {
    if (m_tSpare.empty()) {
      m_tReadings.emplace_back();
    } else {
      m_tReadings.push_back(std::move(m_tSpare.back()));
      m_tSpare.pop_back();
    }
  }
  for (size_t i = 0; i < unCount; ++i) {
    const essaim::ArgosRabPacket sIn = m_pcRobotIo->Rab(static_cast<int>(i));
    SPacket& sPacket = m_tReadings[i];
    sPacket.Range = sIn.range;
    sPacket.HorizontalBearing = CRadians(sIn.horizontal_bearing);
    sPacket.VerticalBearing = CRadians(sIn.vertical_bearing);
    sPacket.Data.Assign(sIn.data, static_cast<size_t>(sIn.size));
  }
}
void CRangeAndBearingMediumSensor::Reset() {
  while (!m_tReadings.empty()) {
    m_tSpare.push_back(std::move(m_tReadings.back()));
    m_tReadings.pop_back();
  }
}

CColoredBlobOmnidirectionalCameraRotZOnlySensor::~CColoredBlobOmnidirectionalCameraRotZOnlySensor() {
  for (SBlob* psBlob : m_vecBlobs) delete psBlob;
}

// The blob list points into the sensor's own blobs, made once each and refilled in place.
void CColoredBlobOmnidirectionalCameraRotZOnlySensor::Update() {
  if (IsDisabled()) return;
  ++m_sReadings.Counter;
  const size_t unCount = static_cast<size_t>(m_pcRobotIo->BlobCount());
  while (m_vecBlobs.size() < unCount) m_vecBlobs.push_back(new SBlob);
  m_sReadings.BlobList.clear();
  for (size_t i = 0; i < unCount; ++i) {
    const essaim::ArgosBlob sIn = m_pcRobotIo->Blob(static_cast<int>(i));
    SBlob& sBlob = *m_vecBlobs[i];
    sBlob.Color.Set(sIn.color.r, sIn.color.g, sIn.color.b, sIn.alpha);
    sBlob.Angle = CRadians(sIn.angle);
    sBlob.Distance = sIn.distance;
    m_sReadings.BlobList.push_back(&sBlob);
  }
}
void CColoredBlobOmnidirectionalCameraRotZOnlySensor::Reset() {
  m_sReadings.Counter = 0;
  m_sReadings.BlobList.clear();
}
// The robot's camera looks only while enabled (the host's readings have no blobs otherwise).
void CColoredBlobOmnidirectionalCameraRotZOnlySensor::Enable() {
  m_pcRobotIo->SetCameraEnabled(true);
  CCI_Sensor::Enable();
}
void CColoredBlobOmnidirectionalCameraRotZOnlySensor::Disable() {
  m_pcRobotIo->SetCameraEnabled(false);
  CCI_Sensor::Disable();
}

}  // namespace argos
