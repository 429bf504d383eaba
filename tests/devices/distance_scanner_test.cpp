// Distance scanner: −1 / −2 readings, ray height, position and rotating modes
// with their angles, sorted and de-duplicated arrays, starts OFF, one-tick latency,
// exact argument counts, the Lua arrays.
#include <gtest/gtest.h>

#include <cmath>

#include "devices/devices.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

constexpr double kR = footbot::kRadius;

std::string Controller(const std::string& script, bool actuator = true) {
  return std::string("<lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/>") +
         (actuator ? "<footbot_distance_scanner implementation=\"default\"/>" : "") +
         "</actuators><sensors><footbot_distance_scanner implementation=\"rot_z_only\" show_rays=\"false\" "
         "noise_range=\"-1:1\"/></sensors><params script=\"" +
         script + "\"/></lua_controller>";
}

/// Front wall 10 cm from the body, left wall 5 cm (inside the long range's 12 cm), right
/// wall 50 cm; nothing behind.
std::string Walls() {
  return Box("front", kR + 0.10 + 0.05, 0, 0.1, 0.4, 0.5) + Box("left", 0, kR + 0.05 + 0.05, 0.2, 0.1, 0.5) +
         Box("right", 0, -(kR + 0.5 + 0.05), 0.2, 0.1, 0.5);
}

Scene LoadScript(const TempDir& d, const std::string& lua, const std::string& arena, bool actuator = true,
                 std::vector<std::string>* log = nullptr) {
  d.Write("c.lua", lua);
  SimOptions so;
  if (log) so.log_sink = [log](char, const std::string& l, const LogOrigin&) { log->push_back(l); };
  return Load(d, Experiment(FootBot("fb0", 0, 0, 0, "c") + arena, Controller("c.lua", actuator)), {}, so);
}

TEST(Scanner, PositionModeTooCloseNothingAndDistances) {
  TempDir d;
  Scene s = LoadScript(d, "function init() robot.distance_scanner.set_angle(0) end function step() end", Walls());
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  const Readings& rd = s.world->robots[0].rd;
  ASSERT_EQ(rd.scanner_short_count, 2);
  ASSERT_EQ(rd.scanner_long_count, 2);
  // Short: front (0) 10 cm, back (π) nothing. Sorted by angle.
  EXPECT_NEAR(rd.scanner_short[0].angle, 0, 1e-12);
  EXPECT_NEAR(rd.scanner_short[0].distance, 10.0, 1e-4);
  EXPECT_NEAR(rd.scanner_short[1].angle, kPi, 1e-12);
  EXPECT_EQ(rd.scanner_short[1].distance, -2);
  // Long: right (−π/2) 50 cm, left (π/2) 5 cm ≤ 12 cm → too close.
  EXPECT_NEAR(rd.scanner_long[0].angle, -kPi / 2, 1e-12);
  EXPECT_NEAR(rd.scanner_long[0].distance, 50.0, 1e-4);
  EXPECT_NEAR(rd.scanner_long[1].angle, kPi / 2, 1e-12);
  EXPECT_EQ(rd.scanner_long[1].distance, -1);
}

TEST(Scanner, AnglesAreRelativeToTheBodyAndSignedNormalized) {
  TempDir d;
  // set_angle(−π/2): platform stored as 3π/2; short at −π/2 and π/2, long at 0 and π.
  Scene s = LoadScript(d, "function init() robot.distance_scanner.set_angle(-math.pi / 2) end function step() end", "");
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  const Readings& rd = s.world->robots[0].rd;
  EXPECT_NEAR(s.world->robots[0].scanner.rotation, 1.5 * kPi, 1e-12);
  ASSERT_EQ(rd.scanner_short_count, 2);
  ASSERT_EQ(rd.scanner_long_count, 2);
  EXPECT_NEAR(rd.scanner_short[0].angle, -kPi / 2, 1e-12);
  EXPECT_NEAR(rd.scanner_short[1].angle, kPi / 2, 1e-12);
  EXPECT_NEAR(rd.scanner_long[0].angle, 0, 1e-12);
  EXPECT_NEAR(rd.scanner_long[1].angle, kPi, 1e-12);
}

TEST(Scanner, RaysAreAtScannerHeight) {
  TempDir d;
  // 12 cm high: below the 12.32 cm platform, invisible to the scanner (but not to proximity).
  Scene s = LoadScript(d, "function init() robot.distance_scanner.enable() end function step() end",
                       Box("low", kR + 0.10 + 0.05, 0, 0.1, 0.4, 0.12));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  const Readings& rd = s.world->robots[0].rd;
  ASSERT_EQ(rd.scanner_short_count, 2);
  EXPECT_EQ(rd.scanner_short[0].distance, -2);
}

TEST(Scanner, RotatingSixRaysPerSensorPerTickSortedByAngle) {
  TempDir d;
  // 100 rpm at 10 ticks/s: π/3 per tick, so rays every π/18 (10°).
  Scene s = LoadScript(d, "function init() robot.distance_scanner.set_rpm(100) end function step() end", Walls());
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  const Readings& rd = s.world->robots[0].rd;
  EXPECT_NEAR(s.world->robots[0].scanner.rotation, kPi / 3, 1e-12);
  ASSERT_EQ(rd.scanner_short_count, 12);
  ASSERT_EQ(rd.scanner_long_count, 12);
  // Short: 0..50° and 180..230° → −170..−130°, 0..50°, 180°.
  const double short_deg[12] = {-170, -160, -150, -140, -130, 0, 10, 20, 30, 40, 50, 180};
  const double long_deg[12] = {-90, -80, -70, -60, -50, -40, 90, 100, 110, 120, 130, 140};
  for (int i = 0; i < 12; ++i) {
    EXPECT_NEAR(rd.scanner_short[i].angle, DegToRad(short_deg[i]), 1e-9) << i;
    EXPECT_NEAR(rd.scanner_long[i].angle, DegToRad(long_deg[i]), 1e-9) << i;
  }
  // The front wall: 10 cm straight ahead, X/cos(10°) − r at 10°.
  EXPECT_NEAR(rd.scanner_short[5].distance, 10.0, 1e-4);
  EXPECT_NEAR(rd.scanner_short[6].distance, 100 * ((kR + 0.1) / std::cos(DegToRad(10)) - kR), 1e-4);
  // Next tick sweeps 60..110°: short 60..110 and −120..−70.
  RunTicks(*s.world, 1);
  const double short2[12] = {-120, -110, -100, -90, -80, -70, 60, 70, 80, 90, 100, 110};
  ASSERT_EQ(rd.scanner_short_count, 12);
  for (int i = 0; i < 12; ++i) EXPECT_NEAR(rd.scanner_short[i].angle, DegToRad(short2[i]), 1e-9) << i;
}

TEST(Scanner, ZeroRpmGivesOneReadingPerSensor) {
  TempDir d;
  Scene s = LoadScript(d, "function init() robot.distance_scanner.set_rpm(0) end function step() end", "");
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 2);
  const Readings& rd = s.world->robots[0].rd;
  EXPECT_EQ(rd.scanner_short_count, 2);  // six equal angles overwrite each other
  EXPECT_EQ(rd.scanner_long_count, 2);
}

TEST(Scanner, NegativeRpmIsSweptCounterClockwiseAsInArgos) {
  TempDir d;
  // −100 rpm: the platform goes to 5π/3, and the sweep 0 → 5π/3 is taken CCW (quirk).
  Scene s = LoadScript(d, "function init() robot.distance_scanner.set_rpm(-100) end function step() end", "");
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 1);
  const Readings& rd = s.world->robots[0].rd;
  EXPECT_NEAR(s.world->robots[0].scanner.rotation, 5 * kPi / 3, 1e-9);
  ASSERT_EQ(rd.scanner_short_count, 12);
  // Rays every 50°: 0..250° and 180..430°, signed and sorted.
  const double deg[12] = {-160, -130, -110, -80, -30, 0, 20, 50, 70, 100, 150, 180};
  for (int i = 0; i < 12; ++i) EXPECT_NEAR(rd.scanner_short[i].angle, DegToRad(deg[i]), 1e-9) << i;
}

TEST(Scanner, StartsOffAndCommandsActNextTick) {
  TempDir d;
  std::vector<std::string> log;
  Scene s = LoadScript(d, R"(
local ds = robot.distance_scanner
function init()
  assert(type(ds.short_range) == "table" and #ds.short_range == 0 and #ds.long_range == 0)
  assert(ds.locked == nil)
end
n = 0
function step()
  n = n + 1
  log(n .. " " .. #ds.short_range .. " " .. #ds.long_range)
  if n == 2 then ds.enable() end
  if n == 4 then
    assert(math.abs(ds.short_range[1].angle) < 1e-12)   -- platform at 0
    ds.set_angle(math.pi / 2)
  end
  if n == 5 then assert(math.abs(ds.short_range[1].angle + math.pi / 2) < 1e-12) end   -- now at π/2
  if n == 6 then ds.set_rpm(100) end
  if n == 8 then ds.disable() end
end
)",
                       "", true, &log);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 9);
  ASSERT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
  const std::vector<std::string> expect = {"1 0 0", "2 0 0",   "3 2 2",   "4 2 2", "5 2 2",
                                           "6 2 2", "7 12 12", "8 12 12", "9 0 0"};
  EXPECT_EQ(log, expect);
}

TEST(Scanner, LuaArraysHoldAngleDistanceSortedAndShrink) {
  TempDir d;
  Scene s = LoadScript(d, R"(
local ds = robot.distance_scanner
function init() ds.set_rpm(100) end
n = 0
function step()
  n = n + 1
  if n == 1 then
    local sr = ds.short_range
    assert(#sr == 12, #sr)
    for i = 2, 12 do assert(sr[i].angle > sr[i - 1].angle) end
    assert(math.abs(sr[6].angle) < 1e-12 and math.abs(sr[6].distance - 10) < 1e-4, sr[6].distance)
    assert(sr[1].distance == -2)
    assert(math.abs(ds.long_range[12].angle - math.rad(140)) < 1e-9)
    ds.set_angle(0)
  elseif n == 2 then
    -- set_angle(0) of the previous step has acted: back to 2 + 2, the tail is nil
    assert(#ds.short_range == 2 and ds.short_range[3] == nil, #ds.short_range)
    assert(ds.short_range[1].angle == 0 and math.abs(ds.short_range[1].distance - 10) < 1e-4)
    assert(ds.long_range[2].distance == -1)
  end
end
)",
                       Walls());
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 2);
  ASSERT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
}

TEST(Scanner, ExactArgumentCounts) {
  for (const char* call :
       {"robot.distance_scanner.enable(1)", "robot.distance_scanner.disable(0)", "robot.distance_scanner.set_angle()",
        "robot.distance_scanner:set_angle(1)", "robot.distance_scanner.set_rpm(1, 2)"}) {
    TempDir d;
    Scene s = LoadScript(d, std::string("function init() ") + call + " end function step() end", "");
    ASSERT_TRUE(s.ok()) << s.error;
    ASSERT_EQ(s.world->controller_errors.size(), 1u) << call;
    EXPECT_NE(s.world->controller_errors[0].message.find("robot.distance_scanner."), std::string::npos)
        << s.world->controller_errors[0].message;
  }
  TempDir d;
  Scene s = LoadScript(d, "function init() robot.distance_scanner.set_rpm('x') end function step() end", "");
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_EQ(s.world->controller_errors.size(), 1u);
}

TEST(Scanner, SensorWithoutActuatorStaysOff) {
  TempDir d;
  Scene s = LoadScript(d, R"(
function init() assert(robot.distance_scanner.enable == nil) end
function step() assert(#robot.distance_scanner.short_range == 0) end
)",
                       Walls(), false);
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 2);
  ASSERT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
}

}  // namespace
}  // namespace essaim
