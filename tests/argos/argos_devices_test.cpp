// The sensors and actuators a C++ controller gets, over fake robot readings: each ARGoS
// reading layout filled from the robot's values, the enabled flags ARGoS's Init leaves,
// the camera's timing, buffers reused from tick to tick, and each actuator's effect.
#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_base_ground_sensor.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_distance_scanner_actuator.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_distance_scanner_sensor.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_gripper_actuator.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_light_sensor.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_motor_ground_sensor.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_proximity_sensor.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_turret_actuator.h>
#include <argos3/plugins/robots/foot-bot/control_interface/ci_footbot_turret_encoder_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_battery_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_colored_blob_omnidirectional_camera_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_differential_steering_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_leds_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_positioning_sensor.h>
#include <argos3/plugins/robots/generic/control_interface/ci_range_and_bearing_actuator.h>
#include <argos3/plugins/robots/generic/control_interface/ci_range_and_bearing_sensor.h>
#include <gtest/gtest.h>

#include <functional>

#include "argos/argos_fakes.h"
#include "argos/argos_session.h"

using namespace argos;
using essaim::ArgosControllerSpec;
using essaim::ArgosSession;

namespace {
// Every device the foot-bot's C++ controllers may declare, fetched in Init.
class CDeviceProbe : public CCI_Controller {
 public:
  void Init(TConfigurationNode&) override {
    proximity = GetSensor<CCI_FootBotProximitySensor>("footbot_proximity");
    light = GetSensor<CCI_FootBotLightSensor>("footbot_light");
    motor_ground = GetSensor<CCI_FootBotMotorGroundSensor>("footbot_motor_ground");
    base_ground = GetSensor<CCI_FootBotBaseGroundSensor>("footbot_base_ground");
    positioning = GetSensor<CCI_PositioningSensor>("positioning");
    steering = GetSensor<CCI_DifferentialSteeringSensor>("differential_steering");
    rab = GetSensor<CCI_RangeAndBearingSensor>("range_and_bearing");
    camera = GetSensor<CCI_ColoredBlobOmnidirectionalCameraSensor>("colored_blob_omnidirectional_camera");
    battery = GetSensor<CCI_BatterySensor>("battery");
    scanner = GetSensor<CCI_FootBotDistanceScannerSensor>("footbot_distance_scanner");
    encoder = GetSensor<CCI_FootBotTurretEncoderSensor>("footbot_turret_encoder");
    wheels = GetActuator<CCI_DifferentialSteeringActuator>("differential_steering");
    leds = GetActuator<CCI_LEDsActuator>("leds");
    rab_out = GetActuator<CCI_RangeAndBearingActuator>("range_and_bearing");
    gripper = GetActuator<CCI_FootBotGripperActuator>("footbot_gripper");
    turret = GetActuator<CCI_FootBotTurretActuator>("footbot_turret");
    scanner_out = GetActuator<CCI_FootBotDistanceScannerActuator>("footbot_distance_scanner");
  }
  void ControlStep() override {
    if (step) step();
  }
  CCI_FootBotProximitySensor* proximity;
  CCI_FootBotLightSensor* light;
  CCI_FootBotMotorGroundSensor* motor_ground;
  CCI_FootBotBaseGroundSensor* base_ground;
  CCI_PositioningSensor* positioning;
  CCI_DifferentialSteeringSensor* steering;
  CCI_RangeAndBearingSensor* rab;
  CCI_ColoredBlobOmnidirectionalCameraSensor* camera;
  CCI_BatterySensor* battery;
  CCI_FootBotDistanceScannerSensor* scanner;
  CCI_FootBotTurretEncoderSensor* encoder;
  CCI_DifferentialSteeringActuator* wheels;
  CCI_LEDsActuator* leds;
  CCI_RangeAndBearingActuator* rab_out;
  CCI_FootBotGripperActuator* gripper;
  CCI_FootBotTurretActuator* turret;
  CCI_FootBotDistanceScannerActuator* scanner_out;
  std::function<void()> step;
};
CDeviceProbe* g_probe = nullptr;

class CDeviceProbeMade : public CDeviceProbe {
 public:
  CDeviceProbeMade() { g_probe = this; }
};
}  // namespace

REGISTER_CONTROLLER(CDeviceProbeMade, "device_probe")

namespace {
std::string DeviceProbeLibrary() {
  for (const essaim::ArgosRegistration& r : essaim::ArgosRegisteredControllers())
    if (r.label == "device_probe") return r.library;
  return "";
}

class ArgosDevices : public ::testing::Test {
 protected:
  void SetUp() override {
    ArgosControllerSpec spec{"device_probe", "ctl", "test.argos:3", {}};
    for (const char* tag : {"footbot_proximity", "footbot_turret_encoder", "positioning", "battery"})
      spec.devices.push_back({tag, "default", true});
    for (const char* tag : {"footbot_light", "footbot_motor_ground", "footbot_base_ground",
                            "colored_blob_omnidirectional_camera", "footbot_distance_scanner"})
      spec.devices.push_back({tag, "rot_z_only", true});
    spec.devices.push_back({"differential_steering", "default", true});
    spec.devices.push_back({"range_and_bearing", "medium", true});
    for (const char* tag : {"differential_steering", "leds", "range_and_bearing", "footbot_gripper", "footbot_turret",
                            "footbot_distance_scanner"})
      spec.devices.push_back({tag, "default", false});
    ASSERT_TRUE(session.CreateController(0, "fb0", {DeviceProbeLibrary()}, spec, &io, &error)) << error;
    ticpp::Element params("params");
    ASSERT_TRUE(session.InitController(0, params, &error)) << error;
    probe = g_probe;
  }
  void Step() { ASSERT_TRUE(session.StepController(0, &error)) << error; }

  essaim::FakeWorld world;
  ArgosSession session{&world};
  essaim::FakeRobotIo io;
  std::string error;
  CDeviceProbe* probe = nullptr;
};
}  // namespace

TEST_F(ArgosDevices, InitLeavesTheEnabledFlagsAsArgossInit) {
  EXPECT_FALSE(probe->proximity->IsEnabled());  // it reads anyway
  EXPECT_TRUE(probe->camera->IsDisabled());
  EXPECT_FALSE(io.camera);
  for (CCI_Sensor* s : std::initializer_list<CCI_Sensor*>{probe->light, probe->motor_ground, probe->base_ground,
                                                          probe->positioning, probe->steering, probe->rab})
    EXPECT_TRUE(s->IsEnabled());
}

TEST_F(ArgosDevices, TheLayoutsStartAsArgoss) {
  ASSERT_EQ(probe->proximity->GetReadings().size(), 24u);
  EXPECT_DOUBLE_EQ(probe->proximity->GetReadings()[0].Angle.GetValue(), ARGOS_PI / 24);
  EXPECT_NEAR(probe->proximity->GetReadings()[23].Angle.GetValue(), -ARGOS_PI / 24, 1e-12);
  ASSERT_EQ(probe->light->GetReadings().size(), 24u);
  ASSERT_EQ(probe->motor_ground->GetReadings().size(), 4u);
  EXPECT_EQ(probe->motor_ground->GetReadings()[1].Offset, CVector2(-6.3, 1.16));
  ASSERT_EQ(probe->base_ground->GetReadings().size(), 8u);
  EXPECT_EQ(probe->base_ground->GetReadings()[3].Offset, CVector2(-4.2, 6.5));
  EXPECT_EQ(probe->rab_out->GetSize(), 4u);
  EXPECT_EQ(probe->leds->GetNumLEDs(), 13u);
  EXPECT_EQ(probe->battery->GetReading().AvailableCharge, 1.0);
  EXPECT_DOUBLE_EQ(CCI_FootBotGripperActuator::LOCKED_POSITIVE.GetValue(), ARGOS_PI / 2);
  EXPECT_DOUBLE_EQ(CCI_FootBotGripperActuator::LOCKED_NEGATIVE.GetValue(), -ARGOS_PI / 2);
  EXPECT_EQ(CCI_FootBotGripperActuator::UNLOCKED.GetValue(), 0.0);
}

TEST_F(ArgosDevices, ReadingsComeFromTheRobotEachStep) {
  for (int i = 0; i < 24; ++i) io.proximity[i] = i / 100.0, io.proximity_angles[i] = i * 0.25, io.light[i] = i / 50.0;
  for (int i = 0; i < 4; ++i) io.motor_ground[i] = 0.1 * i, io.motor_offsets[i][0] = i, io.motor_offsets[i][1] = -i;
  for (int i = 0; i < 8; ++i) io.base_ground[i] = i % 2, io.base_offsets[i][0] = 2 * i, io.base_offsets[i][1] = 1;
  io.position[0] = 1.5, io.position[1] = -0.5, io.position[2] = 0.1;
  io.quaternion[0] = std::cos(0.3), io.quaternion[3] = std::sin(0.3);
  io.wheel_velocity[0] = 5, io.wheel_velocity[1] = 6, io.wheel_distance[0] = 0.5, io.wheel_distance[1] = 0.6;
  io.charge = 0.75, io.time_left = 40, io.turret_rotation = 0.4;
  io.short_scans = {{0.1, 12}, {1.6, -1}}, io.long_scans = {{0.8, 70}};
  Step();
  EXPECT_EQ(probe->proximity->GetReadings()[7].Value, 0.07);
  EXPECT_EQ(probe->proximity->GetReadings()[7].Angle.GetValue(), 1.75);
  EXPECT_EQ(probe->light->GetReadings()[10].Value, 0.2);
  EXPECT_EQ(probe->light->GetReadings()[10].Angle.GetValue(), 2.5);
  EXPECT_EQ(probe->motor_ground->GetReadings()[3].Value, 0.1 * 3);
  EXPECT_EQ(probe->motor_ground->GetReadings()[3].Offset, CVector2(3, -3));
  EXPECT_EQ(probe->base_ground->GetReadings()[5].Value, 1);
  EXPECT_EQ(probe->base_ground->GetReadings()[5].Offset, CVector2(10, 1));
  EXPECT_EQ(probe->positioning->GetReading().Position, CVector3(1.5, -0.5, 0.1));
  CRadians z, y, x;
  probe->positioning->GetReading().Orientation.ToEulerAngles(z, y, x);
  EXPECT_NEAR(z.GetValue(), 0.6, 1e-12);
  EXPECT_EQ(probe->steering->GetReading().VelocityRightWheel, 6);
  EXPECT_EQ(probe->steering->GetReading().CoveredDistanceLeftWheel, 0.5);
  EXPECT_EQ(probe->steering->GetReading().WheelAxisLength, 14);
  EXPECT_EQ(probe->battery->GetReading().AvailableCharge, 0.75);
  EXPECT_EQ(probe->battery->GetReading().TimeLeft, 40);
  EXPECT_EQ(probe->encoder->GetRotation().GetValue(), 0.4);
  EXPECT_EQ(probe->scanner->GetShortReadingsMap().size(), 2u);
  EXPECT_EQ(probe->scanner->GetLongReadingsMap().at(CRadians(0.8)), 70);
  EXPECT_EQ(probe->scanner->GetReadingsMap().size(), 3u);
  io.short_scans = {{0.2, 13}}, io.long_scans = {{0.8, 71}, {0.2, 72}};  // the maps' nodes reused
  Step();
  EXPECT_EQ(probe->scanner->GetShortReadingsMap().size(), 1u);
  EXPECT_EQ(probe->scanner->GetLongReadingsMap().at(CRadians(0.8)), 71);
  EXPECT_EQ(probe->scanner->GetReadingsMap().size(), 2u);
  EXPECT_EQ(probe->scanner->GetReadingsMap().at(CRadians(0.2)), 72);  // long after short, the last
}

// Packets' data are copied; PopFront reads network byte order.
TEST_F(ArgosDevices, RangeAndBearingPacketsCarryTheSendersBytes) {
  const uint8_t first[4] = {0, 0, 1, 2}, second[2] = {7, 9};
  io.rab = {{55, 0.5, 0.0, first, 4}, {120, -1.0, 0.1, second, 2}};
  Step();
  const CCI_RangeAndBearingSensor::TReadings& readings = probe->rab->GetReadings();
  ASSERT_EQ(readings.size(), 2u);
  EXPECT_EQ(readings[0].Range, 55);
  EXPECT_EQ(readings[0].HorizontalBearing.GetValue(), 0.5);
  EXPECT_EQ(readings[1].VerticalBearing.GetValue(), 0.1);
  CCI_RangeAndBearingSensor::SPacket packet = readings[0];
  EXPECT_EQ(packet.Data.PopFront<UInt32>(), 258u);
  EXPECT_EQ(readings[1].Data[1], 9);
  const UInt8* buffer = readings[0].Data.ToCArray();
  io.rab.resize(1);
  Step();
  ASSERT_EQ(probe->rab->GetReadings().size(), 1u);
  io.rab = {{55, 0.5, 0.0, first, 4}, {120, -1.0, 0.1, second, 2}};
  Step();
  EXPECT_EQ(probe->rab->GetReadings()[0].Data.ToCArray(), buffer);  // the same buffer, refilled
  EXPECT_EQ(probe->rab->GetReadings()[1].Data[0], 7);
}

// Blobs show from the step after Enable(); Counter counts the updates taken while enabled.
TEST_F(ArgosDevices, TheCameraSeesFromTheStepAfterEnable) {
  io.blobs = {{30, 0.5, {255, 0, 0}, 255}, {60, -0.5, {0, 0, 255}, 128}};
  probe->step = [&] { probe->camera->Enable(); };
  Step();
  EXPECT_TRUE(io.camera);
  EXPECT_TRUE(probe->camera->GetReadings().BlobList.empty());
  EXPECT_EQ(probe->camera->GetReadings().Counter, 0u);
  probe->step = nullptr;
  Step();
  const auto& readings = probe->camera->GetReadings();
  ASSERT_EQ(readings.BlobList.size(), 2u);
  EXPECT_EQ(readings.Counter, 1u);
  EXPECT_EQ(readings.BlobList[0]->Color, CColor::RED);
  EXPECT_EQ(readings.BlobList[1]->Color, CColor(0, 0, 255, 128));
  EXPECT_EQ(readings.BlobList[1]->Angle.GetValue(), -0.5);
  EXPECT_EQ(readings.BlobList[0]->Distance, 30);
  CCI_ColoredBlobOmnidirectionalCameraSensor::SBlob* blob = readings.BlobList[0];
  io.blobs[0].distance = 31;
  Step();
  EXPECT_EQ(readings.Counter, 2u);
  EXPECT_EQ(readings.BlobList[0], blob);  // the same blob, refilled
  EXPECT_EQ(blob->Distance, 31);
  probe->step = [&] { probe->camera->Disable(); };
  Step();
  EXPECT_FALSE(io.camera);
  probe->step = nullptr;
  Step();
  EXPECT_EQ(readings.Counter, 3u);  // disabled: no update, the last blobs stay (as ARGoS's)
  ASSERT_TRUE(session.ResetController(0, &error)) << error;
  EXPECT_EQ(readings.Counter, 0u);
  EXPECT_TRUE(readings.BlobList.empty());
}

TEST_F(ArgosDevices, WheelsLedsAndGripperReachTheRobot) {
  probe->step = [&] {
    probe->wheels->SetLinearVelocity(10, -4);
    probe->leds->SetSingleColor(12, CColor::RED);
    probe->leds->SetSingleIntensity(3, 100);
    probe->gripper->LockPositive();
  };
  Step();
  EXPECT_EQ(io.wheels[0], 10);
  EXPECT_EQ(io.wheels[1], -4);
  EXPECT_EQ(io.leds[12].color.r, 255);
  EXPECT_EQ(io.leds[12].alpha, 255);
  EXPECT_EQ(io.leds[3].color.r, 0);
  EXPECT_EQ(io.leds[3].alpha, 100);  // an intensity is the colour's alpha
  EXPECT_EQ(io.leds[0].sets, 1);     // black after Init, as ARGoS's; then only what changed
  EXPECT_EQ(io.leds[12].sets, 2);
  EXPECT_DOUBLE_EQ(io.gripper, ARGOS_PI / 2);
  probe->step = [&] {
    probe->leds->SetAllColors(CColor::GREEN);
    probe->leds->SetAllIntensities(50);
    probe->gripper->SetAperture(CRadians(3.0));  // kept within the locks
  };
  Step();
  for (const essaim::FakeLed& led : io.leds) {
    EXPECT_EQ(led.color.g, 255);
    EXPECT_EQ(led.alpha, 50);
  }
  EXPECT_DOUBLE_EQ(io.gripper, ARGOS_PI / 2);
  probe->step = [&] { probe->leds->SetSingleColor(13, CColor::RED); };
  EXPECT_FALSE(session.StepController(0, &error));
  EXPECT_NE(error.find("LED 13 does not exist"), std::string::npos) << error;
  ASSERT_TRUE(session.ResetController(0, &error)) << error;
  EXPECT_EQ(io.wheels[0], 0);
  EXPECT_EQ(io.leds[12].color.g, 0);  // reset to black
  EXPECT_EQ(io.gripper, 0);           // unlocked
}

TEST_F(ArgosDevices, RangeAndBearingDataIsCheckedAndSent) {
  probe->step = [&] {
    CByteArray data;
    data << UInt32(0x01020304);
    probe->rab_out->SetData(data);
  };
  Step();
  EXPECT_EQ(io.rab_data, (std::vector<uint8_t>{1, 2, 3, 4}));
  probe->step = [&] { probe->rab_out->SetData(1, 99); };
  Step();
  EXPECT_EQ(io.rab_data[1], 99);
  probe->step = [&] { probe->rab_out->SetData(4, 1); };  // past the end: ARGoS's CByteArray throws
  EXPECT_FALSE(session.StepController(0, &error));
  EXPECT_NE(error.find("CByteArray: index out of bounds [index = 4, size=4]"), std::string::npos) << error;
  probe->step = [&] { probe->rab_out->SetData(CByteArray(3)); };
  EXPECT_FALSE(session.StepController(0, &error));
  EXPECT_NE(error.find("data size does not match, expected 4, got 3"), std::string::npos) << error;
  probe->step = [&] { probe->rab_out->ClearData(); };
  Step();
  EXPECT_EQ(io.rab_data, (std::vector<uint8_t>{0, 0, 0, 0}));
}

TEST_F(ArgosDevices, TurretAndScannerCallsAreTheLuaTablesOperations) {
  probe->step = [&] {
    probe->turret->SetActiveWithRotation(CRadians(0.5));
    probe->turret->SetSpeedControlMode();
    probe->turret->SetRotationSpeed(3);
    probe->scanner_out->Enable();
    probe->scanner_out->SetRPM(60);
    probe->scanner_out->SetAngle(CRadians(1.0));
  };
  Step();
  EXPECT_EQ(io.calls, (std::vector<std::string>{"turret mode 2", "turret rotation 0.500000", "turret mode 3",
                                                "turret speed 3.000000", "scanner enable", "scanner rpm 60.000000",
                                                "scanner angle 1.000000"}));
}

TEST(ArgosByteArray, IntegersGoInAndOutInNetworkOrder) {
  CByteArray data;
  data << UInt8(1) << UInt16(0x0203) << UInt32(0x04050607) << UInt64(0x08090A0B0C0D0E0FULL) << SInt16(-2)
       << std::string("hi");
  EXPECT_EQ(data.Size(), 1u + 2 + 4 + 8 + 2 + 3);
  EXPECT_EQ(data[1], 2);
  EXPECT_EQ(data[3], 4);
  EXPECT_EQ(data.PopFront<UInt8>(), 1);
  EXPECT_EQ(data.PopFront<UInt16>(), 0x0203);
  EXPECT_EQ(data.PopFront<UInt32>(), 0x04050607u);
  EXPECT_EQ(data.PopFront<UInt64>(), 0x08090A0B0C0D0E0FULL);
  EXPECT_EQ(data.PopFront<SInt16>(), -2);
  EXPECT_EQ(data.PopFront<std::string>(), "hi");
  EXPECT_THROW(data.PopFront<UInt8>(), CARGoSException);
  CByteArray zeros(3, 7);
  zeros.Zero();
  EXPECT_EQ(zeros, CByteArray(3));
}

TEST(ArgosColor, NamesValuesAndTheUInt32Key) {
  CColor c;
  c.Set("orange");
  EXPECT_EQ(c, CColor::ORANGE);
  c.Set("1,2,3,4");
  EXPECT_EQ(c, CColor(1, 2, 3, 4));
  EXPECT_EQ(static_cast<UInt32>(c), 0x04030201u);
  EXPECT_THROW(c.Set("mauve"), CARGoSException);
  EXPECT_THROW(c.Set("1,2,300,4"), CARGoSException);
  CRange<CDegrees> range;
  std::istringstream("-5:5") >> range;
  EXPECT_EQ(range.GetMin().GetValue(), -5);
  EXPECT_EQ(ToRadians(range.GetMax()).GetValue(), 5 * ARGOS_PI / 180);
}
