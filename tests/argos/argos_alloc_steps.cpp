// No heap churn in a C++ controller's step: once its readings are sized (a few warm-up
// steps), StepController with every sensor and actuator declared makes no C++ allocation
// (operator new is counted here, in an executable of its own as tests/sim/alloc_test.cpp).
#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_distance_scanner_sensor.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_gripper_actuator.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_proximity_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_colored_blob_omnidirectional_camera_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_leds_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_range_and_bearing_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_range_and_bearing_sensor.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "argos/argos_fakes.h"
#include "argos/argos_session.h"

namespace {
std::atomic<long> g_news{0};
}
void* operator new(std::size_t n) {
  g_news.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  g_news.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

using namespace argos;

namespace {
// Reads every reading and sets every command, as a busy controller does each step.
class CBusy : public CCI_Controller {
 public:
  void Init(TConfigurationNode&) override {
    m_pcProximity = GetSensor<CCI_FootBotProximitySensor>("footbot_proximity");
    m_pcCamera = GetSensor<CCI_ColoredBlobOmnidirectionalCameraSensor>("colored_blob_omnidirectional_camera");
    m_pcRab = GetSensor<CCI_RangeAndBearingSensor>("range_and_bearing");
    m_pcScanner = GetSensor<CCI_FootBotDistanceScannerSensor>("footbot_distance_scanner");
    m_pcWheels = GetActuator<CCI_DifferentialSteeringActuator>("differential_steering");
    m_pcLeds = GetActuator<CCI_LEDsActuator>("leds");
    m_pcRabOut = GetActuator<CCI_RangeAndBearingActuator>("range_and_bearing");
    m_pcGripper = GetActuator<CCI_FootBotGripperActuator>("footbot_gripper");
    m_pcCamera->Enable();
  }
  void ControlStep() override {
    ++m_unStep;
    Real fSum = 0;
    for (const auto& sReading : m_pcProximity->GetReadings()) fSum += sReading.Value;
    for (const auto* psBlob : m_pcCamera->GetReadings().BlobList) fSum += psBlob->Distance;
    for (const auto& sPacket : m_pcRab->GetReadings()) fSum += sPacket.Data[0];
    for (const auto& tReading : m_pcScanner->GetReadingsMap()) fSum += tReading.second;
    m_pcWheels->SetLinearVelocity(fSum, m_unStep % 7);
    m_pcLeds->SetSingleColor(12, m_unStep % 2 ? CColor::RED : CColor::BLUE);
    m_pcLeds->SetAllIntensities(static_cast<UInt8>(m_unStep));
    m_pcRabOut->SetData(0, static_cast<UInt8>(m_unStep));
    if (m_unStep % 2)
      m_pcGripper->LockPositive();
    else
      m_pcGripper->Unlock();
  }

 private:
  CCI_FootBotProximitySensor* m_pcProximity;
  CCI_ColoredBlobOmnidirectionalCameraSensor* m_pcCamera;
  CCI_RangeAndBearingSensor* m_pcRab;
  CCI_FootBotDistanceScannerSensor* m_pcScanner;
  CCI_DifferentialSteeringActuator* m_pcWheels;
  CCI_LEDsActuator* m_pcLeds;
  CCI_RangeAndBearingActuator* m_pcRabOut;
  CCI_FootBotGripperActuator* m_pcGripper;
  UInt32 m_unStep = 0;
};
}  // namespace

REGISTER_CONTROLLER(CBusy, "busy_controller")

TEST(ArgosControllerAlloc, AStepAllocatesNothingOnceSized) {
  essaim::FakeWorld world;
  essaim::ArgosSession session(&world);
  essaim::FakeRobotIo io;
  std::string library, error;
  for (const essaim::ArgosRegistration& r : essaim::ArgosRegisteredControllers())
    if (r.label == "busy_controller") library = r.library;
  essaim::ArgosControllerSpec spec{"busy_controller", "busy", "test.argos:1", {}};
  spec.devices = {{"footbot_proximity", "default", true},
                  {"colored_blob_omnidirectional_camera", "rot_z_only", true},
                  {"range_and_bearing", "medium", true},
                  {"footbot_distance_scanner", "rot_z_only", true},
                  {"positioning", "default", true},
                  {"footbot_motor_ground", "rot_z_only", true},
                  {"differential_steering", "default", false},
                  {"leds", "default", false},
                  {"range_and_bearing", "default", false},
                  {"footbot_gripper", "default", false}};
  ASSERT_TRUE(session.CreateController(0, "fb0", {library}, spec, &io, &error)) << error;
  ticpp::Element params("params");
  ASSERT_TRUE(session.InitController(0, params, &error)) << error;
  const uint8_t payload[4] = {1, 2, 3, 4};
  io.rab = {{50, 0.1, 0, payload, 4}, {70, 0.2, 0, payload, 4}, {90, 0.3, 0, payload, 4}};
  io.blobs = {{30, 0.5, {255, 0, 0}, 255}, {60, -0.5, {0, 0, 255}, 255}};
  io.short_scans = {{0.1, 12}, {1.6, 20}}, io.long_scans = {{0.8, 70}, {2.4, 80}};
  for (int k = 0; k < 6; ++k) {  // each number of neighbours once: the readings' sizes
    io.rab.resize(3 - k % 3, io.rab[0]);
    ASSERT_TRUE(session.StepController(0, &error)) << error;
  }
  io.rab.resize(3, io.rab[0]);
  const long before = g_news.load();
  for (int k = 0; k < 100; ++k) {
    io.rab.resize(1 + k % 3, io.rab[0]);  // neighbours come and go within the sizes seen
    io.short_scans[0].angle = 0.01 * k;   // new angles, the same number of them
    if (!session.StepController(0, &error)) break;
  }
  EXPECT_EQ(error, "");
  EXPECT_EQ(g_news.load() - before, 0);
}
