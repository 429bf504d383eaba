// The device rows: the model's table (device_table.h), the devices layer's functions
// (device_functions.cpp) and the Lua host's tables agree for every DeviceType. The rows'
// completeness is checked at compile time; these tests check what a row means.
#include <gtest/gtest.h>

#include <cstring>

#include "devices/device_functions.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

TEST(DeviceRows, EveryRowIsFoundByItsElementAndKind) {
  for (const DeviceRow& row : kDeviceRows) {
    EXPECT_EQ(FindDevice(row.xml_name, row.is_sensor), &row) << row.xml_name;
    EXPECT_EQ(&GetDeviceRow(row.type), &row) << row.xml_name;
    EXPECT_GT(std::strlen(CostName(row.cost)), 0u) << row.xml_name;
  }
}

TEST(DeviceRows, SensorsSenseAndActuatorsActInTheirHalfOfTheActStage) {
  for (const DeviceRow& row : kDeviceRows) {
    const DeviceFunctions& f = FunctionsOf(row.type);
    EXPECT_EQ(f.type, row.type);
    EXPECT_EQ(row.is_sensor, f.sense != nullptr) << row.xml_name;
    EXPECT_EQ(!row.is_sensor, f.act != nullptr) << row.xml_name;
    // Joints are made in the one physics world: those actuators run on one thread.
    EXPECT_EQ(f.act_phase == ActPhase::Joints, row.cost == DeviceCost::PerJoint) << row.xml_name;
  }
}

TEST(DeviceRows, ActuatorAndSensorOfOneKeyShareTheirLuaTable) {
  TempDir d;
  const std::string script = d.Write("c.lua",
                                     "local wheels\n"
                                     "function init()\n"
                                     "  assert(robot.wheels.set_velocity, 'actuator closure')\n"
                                     "  assert(robot.wheels.axis_length, 'sensor field')\n"
                                     "  assert(robot.battery.available_charge == 1, 'reading visible in init')\n"
                                     "  wheels = robot.wheels\n"
                                     "end\n"
                                     "function step()\n"
                                     "  assert(robot.wheels == wheels, 'the same table every tick')\n"
                                     "  robot.wheels.set_velocity(1, 1)\n"
                                     "end\n");
  Scene s = Load(d, Experiment(FootBot("fb", 0, 0, 0, "c"),
                               WheelsController("c", script, "<battery implementation=\"default\"/>")));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 3);
  EXPECT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors.front().message;
  EXPECT_GT(s.world->robots[0].rd.distance_left, 0) << "set_velocity acted through the actuator's row";
}

}  // namespace
}  // namespace essaim
