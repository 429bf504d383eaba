// LEDs actuator: colours by name, "r,g,b,a" and numbers, applied in the next
// Act stage; errors name the bad colour or index; the 13 LED positions.
#include <gtest/gtest.h>

#include <cmath>

#include "devices/media.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

std::string LedController(const std::string& id, const std::string& script) {
  return "<lua_controller id=\"" + id +
         "\"><actuators><differential_steering implementation=\"default\"/>"
         "<leds implementation=\"default\" medium=\"leds\"/></actuators><sensors/><params script=\"" +
         script + "\"/></lua_controller>";
}

std::string LedExperiment(const std::string& arena, const std::string& controllers) {
  std::string xml = Experiment(arena, controllers, 1000);
  size_t p = xml.find("<media/>");
  xml.replace(p, 8, "<media><led id=\"leds\"/></media>");
  return xml;
}

struct Logged {
  std::vector<std::string> lines;
  Scene s;
};
std::unique_ptr<Logged> LoadLogged(const TempDir& d, const std::string& xml) {
  auto l = std::make_unique<Logged>();
  SimOptions sim;
  Logged* raw = l.get();
  sim.log_sink = [raw](char, const std::string& line, const LogOrigin&) { raw->lines.push_back(line); };
  l->s = Load(d, xml, {}, sim);
  return l;
}

bool Same(const Color& c, int r, int g, int b, int a = 255) { return c.r == r && c.g == g && c.b == b && c.a == a; }

TEST(Leds, ColoursApplyInTheNextAct) {
  TempDir d;
  d.Write(
      "c.lua",
      "n = 0\nfunction init() robot.leds.set_all_colors('red') end\n"
      "function step() n = n + 1\n"
      "  if n == 1 then robot.leds.set_single_color(13, 10, 20, 30); robot.leds.set_single_color(2, '1,2,3,4') end\n"
      "  if n == 2 then robot.leds.set_all_colors(300, 2.9, -1); robot.leds.set_single_color(12.5, 'gray50') end\n"
      "end\n");
  Scene s = Load(d, LedExperiment(FootBot("fb0", 0, 0, 0, "c"), LedController("c", "c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  const RobotState& r = s.world->robots[0];
  for (const Color& c : r.leds) EXPECT_TRUE(Same(c, 0, 0, 0));  // after init: not applied yet
  Step(*s.world);
  for (const Color& c : r.leds) EXPECT_TRUE(Same(c, 255, 0, 0));
  Step(*s.world);
  EXPECT_TRUE(Same(r.leds[12], 10, 20, 30));
  EXPECT_TRUE(Same(r.leds[1], 1, 2, 3, 4));
  EXPECT_TRUE(Same(r.leds[0], 255, 0, 0));
  Step(*s.world);
  EXPECT_TRUE(Same(r.leds[0], 44, 2, 255));      // C++ byte casts: wrap, truncate
  EXPECT_TRUE(Same(r.leds[11], 127, 127, 127));  // index 12.5 -> 12
}

TEST(Leds, ErrorsNameTheColourOrIndex) {
  TempDir d;
  d.Write("c.lua",
          "function init()\n"
          "  for _, f in ipairs({function() robot.leds.set_all_colors('chartreuse') end,\n"
          "                      function() robot.leds.set_all_colors('1,2,3') end,\n"
          "                      function() robot.leds.set_single_color(14, 'red') end,\n"
          "                      function() robot.leds.set_single_color(0, 'red') end,\n"
          "                      function() robot.leds.set_all_colors(1, 2) end,\n"
          "                      function() robot.leds.set_all_colors(5) end}) do\n"
          "    local ok, err = pcall(f); log(ok and 'ok' or err)\n"
          "  end\n"
          "end\nfunction step() end\n");
  auto l = LoadLogged(d, LedExperiment(FootBot("fb0", 0, 0, 0, "c"), LedController("c", "c.lua")));
  ASSERT_TRUE(l->s.ok()) << l->s.error;
  Step(*l->s.world);
  ASSERT_EQ(l->lines.size(), 6u);
  EXPECT_NE(l->lines[0].find("unknown colour 'chartreuse'"), std::string::npos) << l->lines[0];
  EXPECT_NE(l->lines[1].find("unknown colour '1,2,3'"), std::string::npos) << l->lines[1];
  EXPECT_NE(l->lines[2].find("LED index 14"), std::string::npos) << l->lines[2];
  EXPECT_NE(l->lines[3].find("LED index 0"), std::string::npos) << l->lines[3];
  EXPECT_NE(l->lines[4].find("one or three arguments"), std::string::npos) << l->lines[4];
  EXPECT_NE(l->lines[5].find("must be a string"), std::string::npos) << l->lines[5];
  for (const Color& c : l->s.world->robots[0].leds) EXPECT_TRUE(Same(c, 0, 0, 0));
}

TEST(Leds, LoopFunctionsReadAppliedColours) {
  TempDir d;
  d.Write("c.lua", "function init() robot.leds.set_single_color(3, 'cyan') end\nfunction step() end\n");
  d.Write("lf.lua",
          "function post_step() local r, g, b = experiment.robots[1]:led(3); print(r, g, b, math.type(r)) end\n");
  std::string xml = LedExperiment(FootBot("fb0", 0, 0, 0, "c"), LedController("c", "c.lua"));
  xml.replace(xml.find("</argos-configuration>"), 0, "<loop_functions script=\"lf.lua\"/>\n");
  auto l = LoadLogged(d, xml);
  ASSERT_TRUE(l->s.ok()) << l->s.error;
  Step(*l->s.world);
  EXPECT_TRUE(Same(l->s.world->robots[0].leds[2], 0, 255, 255));
  ASSERT_EQ(l->lines.size(), 1u);
  EXPECT_EQ(l->lines[0], "0\t255\t255\tinteger");
}

TEST(Leds, Positions) {
  // Ring LED i at 15° + 30°(i-1) from the heading, 0.090036758 m out, 0.085 m up; the
  // beacon on the axis at 0.174249733 m. The ring turns with the turret.
  Pose2 p{1, 2, kPi / 2};
  Vec3 l1 = FootBotLedPosition(p, 0, 0, 0);
  EXPECT_NEAR(l1.x(), 1 + 0.090036758 * std::cos(DegToRad(105)), 1e-12);
  EXPECT_NEAR(l1.y(), 2 + 0.090036758 * std::sin(DegToRad(105)), 1e-12);
  EXPECT_NEAR(l1.z(), 0.085, 1e-12);
  Vec3 l7 = FootBotLedPosition(p, 0.5, 0, 6);
  EXPECT_NEAR(l7.x(), 1 + 0.090036758 * std::cos(DegToRad(285)), 1e-12);
  EXPECT_NEAR(l7.y(), 2 + 0.090036758 * std::sin(DegToRad(285)), 1e-12);
  EXPECT_NEAR(l7.z(), 0.585, 1e-12);
  Vec3 beacon = FootBotLedPosition(p, 0, 1.0, 12);
  EXPECT_EQ(beacon, Vec3(1, 2, 0.174249733));
  Vec3 turned = FootBotLedPosition(p, 0, kPi / 2, 0);
  EXPECT_NEAR(turned.x(), 1 + 0.090036758 * std::cos(DegToRad(195)), 1e-12);
}

}  // namespace
}  // namespace essaim
