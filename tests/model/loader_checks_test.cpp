// The loader refuses what would run wrong in silence: attributes nobody reads
// (from the file or --set), a controller without a script, robots placed where they cannot be.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "model/device_params.h"
#include "model/device_table.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

const char* kCtrl =
    "<lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/></actuators>"
    "<sensors><footbot_proximity implementation=\"default\" show_rays=\"false\"/></sensors>"
    "<params script=\"c.lua\" speed=\"10\"/></lua_controller>";

const char* kDistribute =
    "<distribute><position method=\"uniform\" min=\"-4,-4,0\" max=\"4,4,0\"/>"
    "<orientation method=\"uniform\" min=\"0,0,0\" max=\"360,0,0\"/>"
    "<entity quantity=\"5\" max_trials=\"100\"><foot-bot id=\"fb\"><controller config=\"c\"/></foot-bot></entity>"
    "</distribute>";

struct Loaded {
  std::unique_ptr<Model> model;
  ErrorList errors, warnings;
  std::string Errors() const { return errors.Format(); }
  std::string Warnings() const { return warnings.Format(); }
};

Loaded LoadWith(const std::string& xml, LoadOptions opt = {}) {
  TempDir d;
  d.Write("c.lua", "function step() end");
  Loaded l;
  l.model = LoadExperimentFile(d.Write("x.argos", xml), opt, &l.errors, &l.warnings);
  return l;
}

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// ---- attributes nobody reads

TEST(UnknownAttributes, SetOfATypoIsAnErrorWithTheClosestName) {
  LoadOptions opt;
  opt.overrides = {"arena.distribute.entity.quantiy=50", "framework.experiment.lenght=3"};
  Loaded l = LoadWith(Experiment(kDistribute, kCtrl), opt);
  EXPECT_FALSE(l.model);
  EXPECT_TRUE(Contains(l.Errors(),
                       "<entity>: --set arena.distribute.entity.quantiy=50: essaim reads no attribute "
                       "'quantiy' on <entity>; did you mean 'quantity'?"))
      << l.Errors();
  EXPECT_TRUE(Contains(l.Errors(), ":2: <experiment>: --set framework.experiment.lenght=3")) << l.Errors();
  EXPECT_TRUE(Contains(l.Errors(), "did you mean 'length'?")) << l.Errors();
}

TEST(UnknownAttributes, SetOfAKnownAttributeWorks) {
  LoadOptions opt;
  opt.overrides = {"arena.distribute.entity.quantity=7", "controllers.c.params.speed=3",
                   "controllers.c.params.brand_new=1", "controllers.c.sensors.footbot_proximity.noise_level=0.1",
                   "arena.positional_index=grid"};
  Loaded l = LoadWith(Experiment(kDistribute, kCtrl), opt);
  ASSERT_TRUE(l.model) << l.Errors();
  EXPECT_EQ(l.model->robots.size(), 7u);
  EXPECT_EQ(l.model->controllers[0].params.at("brand_new"), "1");  // <params> are free-form
}

TEST(UnknownAttributes, SetOnADeviceOrAnIgnoredElementIsChecked) {
  LoadOptions opt;
  opt.overrides = {"controllers.c.sensors.footbot_proximity.noise_levle=0.1", "visualization.qt-opengl.x=1"};
  std::string xml = Experiment(kDistribute, kCtrl, 10, 1, "  <visualization><qt-opengl/></visualization>\n");
  Loaded l = LoadWith(xml, opt);
  EXPECT_FALSE(l.model);
  EXPECT_TRUE(Contains(l.Errors(), "did you mean 'noise_level'?")) << l.Errors();
  EXPECT_TRUE(Contains(l.Errors(), "--set visualization.qt-opengl.x=1: essaim does not read <qt-opengl>"))
      << l.Errors();
}

TEST(UnknownAttributes, ATypoInTheFileIsAWarningAndAnErrorUnderStrict) {
  std::string arena =
      "<light id=\"l\" position=\"1,1,0.5\" orientation=\"0,0,0\" color=\"yellow\" intensty=\"2\" "
      "intensity=\"1\" medium=\"leds\"/>";
  std::string xml = Experiment(arena, kCtrl);
  xml = Replace(xml, "<media/>", "<media><led id=\"leds\"/></media>");
  Loaded l = LoadWith(xml);
  ASSERT_TRUE(l.model) << l.Errors();
  EXPECT_TRUE(Contains(l.Warnings(),
                       ":4: <light>: unknown attribute 'intensty' (essaim does not read it); did you "
                       "mean 'intensity'?"))
      << l.Warnings();
  EXPECT_EQ(l.warnings.Size(), 1u) << l.Warnings();

  LoadOptions strict;
  strict.strict = true;
  Loaded s = LoadWith(xml, strict);
  EXPECT_FALSE(s.model);
  EXPECT_TRUE(Contains(s.Errors(), "unknown attribute 'intensty'")) << s.Errors();
}

// ARGoS's positional entity reads a light's orientation with a default (a light has none
// to speak of): a <light> without it loads, as in ARGoS.
TEST(Loader, ALightNeedsNoOrientation) {
  std::string arena = "<light id=\"l\" position=\"1,1,0.5\" color=\"yellow\" intensity=\"1\" medium=\"leds\"/>";
  std::string xml = Replace(Experiment(arena, kCtrl), "<media/>", "<media><led id=\"leds\"/></media>");
  Loaded l = LoadWith(xml);
  ASSERT_TRUE(l.model) << l.Errors();
  EXPECT_EQ(l.warnings.Size(), 0u) << l.Warnings();
}

TEST(UnknownAttributes, DeviceAttributeTyposAndIgnoredOnesAreTold) {
  std::string ctrl = kCtrl;
  ctrl = Replace(ctrl, "show_rays", "show_rayz");
  Loaded l = LoadWith(Experiment("", ctrl));
  ASSERT_TRUE(l.model) << l.Errors();
  EXPECT_TRUE(Contains(l.Warnings(), "<footbot_proximity>: unknown attribute 'show_rayz'")) << l.Warnings();
  EXPECT_TRUE(Contains(l.Warnings(), "did you mean 'show_rays'?")) << l.Warnings();
}

TEST(UnknownAttributes, AttributesArgosAcceptsAndEssaimIgnoresAreNotTypos) {
  std::string xml =
      Experiment("<foot-bot id=\"fb\" perspective_camera_front=\"true\"><controller config=\"c\"/></foot-bot>", kCtrl);
  xml = Replace(xml, "<framework>",
                "<framework><system threads=\"0\" pin_threads_to_cores=\"false\"/>"
                "<profiling file=\"p.txt\" format=\"table\" truncate_file=\"true\"/>");
  xml = Replace(
      xml, "<dynamics2d id=\"dyn2d\" iterations=\"10\"/>",
      "<dynamics2d id=\"dyn2d\" iterations=\"10\"><spatial_hash cell_size=\"1\" cell_num=\"10\"/></dynamics2d>");
  xml = Replace(xml, "<argos-configuration>",
                "<argos-configuration xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
                "xsi:noNamespaceSchemaLocation=\"argos.xsd\">");
  Loaded l = LoadWith(xml);
  ASSERT_TRUE(l.model) << l.Errors();
  EXPECT_TRUE(l.warnings.Empty()) << l.Warnings();
}

TEST(UnknownAttributes, AnAttributeThatCountsOnlyWithOtherSettingsIsToldSo) {
  std::string arena = Box("a", 2, 2, 1, 1, 0.5) +
                      "<box id=\"b\" size=\"1,1,1\" movable=\"true\" mass=\"2\"><body position=\"-2,-2,0\"/></box>";
  LoadOptions opt;
  opt.overrides = {"arena.a.mass=3"};  // a static box has no mass: a sweep over it changes nothing
  Loaded l = LoadWith(Experiment(arena, kCtrl), opt);
  EXPECT_FALSE(l.model);
  EXPECT_TRUE(Contains(l.Errors(),
                       "--set arena.a.mass=3: essaim reads no attribute 'mass' on <box>; it counts on "
                       "other <box> elements, not with this one's settings"))
      << l.Errors();
}

TEST(UnknownAttributes, ADistributedPrototypeIsCheckedEvenWithQuantityZero) {
  std::string arena = kDistribute;
  arena = Replace(arena, "quantity=\"5\"", "quantity=\"0\"");
  arena = Replace(arena, "<foot-bot id=\"fb\"", "<foot-bot id=\"fb\" rab_rnage=\"2\"");
  Loaded l = LoadWith(Experiment(arena, kCtrl));
  ASSERT_TRUE(l.model) << l.Errors();
  EXPECT_TRUE(Contains(l.Warnings(),
                       "unknown attribute 'rab_rnage' (essaim does not read it); did you mean "
                       "'rab_range'?"))
      << l.Warnings();
}

TEST(UnknownAttributes, UnknownElementsSuggestTheClosestOne) {
  std::string arena = kDistribute;
  arena = Replace(arena, "<orientation", "<orientatoin");
  Loaded l = LoadWith(Experiment(arena, kCtrl));
  EXPECT_FALSE(l.model);
  EXPECT_TRUE(Contains(l.Errors(), "<orientatoin>: unknown element inside <distribute> (did you mean <orientation>?)"))
      << l.Errors();
}

TEST(UnknownAttributes, EveryAttributeDeviceParamsReadsIsInTheDeviceTable) {
  // The device table's rows are the schema for device attributes: a read outside them would
  // flag a user's correct attribute as unknown.
  for (const DeviceRow& row : kDeviceRows) {
    DeviceConfig cfg;
    cfg.type = row.type;
    ErrorList errors;
    ParseDeviceParams(&cfg, &errors);
    EXPECT_TRUE(errors.Empty()) << row.xml_name << ": " << errors.Format();
  }
}

TEST(UnknownAttributes, EveryShippedExperimentLoadsWithoutWarnings) {
  // bench/avoidance_cpp_1000.argos's controller library is built with essaim, into build/bench.
  setenv("ARGOS_PLUGIN_PATH", ESSAIM_BINARY_DIR "/bench", 1);
  int files = 0;
  for (const char* dir : {"arenas", "bench", "tests"}) {
    for (const auto& entry :
         std::filesystem::recursive_directory_iterator(std::string(ESSAIM_SOURCE_DIR) + "/" + dir)) {
      if (entry.path().extension() != ".argos") continue;
      // Fuzz seeds are inputs for the fuzzer (their scripts live in tests/fuzz/data), not experiments.
      if (entry.path().string().find("/tests/fuzz/") != std::string::npos) continue;
      // C++ loop-function projects name libraries their test builds into a temporary folder
      // (tests/argos runs them, and fails on any warning there).
      if (entry.path().string().find("/tests/argos/") != std::string::npos) continue;
      ++files;
      ErrorList errors, warnings;
      LoadOptions opt;
      opt.seed = 1;
      opt.working_dir = entry.path().parent_path().string();
      auto m = LoadExperimentFile(entry.path().string(), opt, &errors, &warnings);
      EXPECT_TRUE(m) << errors.Format();
      EXPECT_TRUE(warnings.Empty()) << warnings.Format();
    }
  }
  unsetenv("ARGOS_PLUGIN_PATH");
  EXPECT_GE(files, 16);
}

// ---- a controller without a script

TEST(ControllerScript, ALuaControllerWithoutScriptIsAnError) {
  std::string ctrl = kCtrl;
  ctrl = Replace(ctrl, "script=\"c.lua\" ", "");
  Loaded l = LoadWith(Experiment(FootBot("fb", 0, 0, 0, "c"), ctrl));
  EXPECT_FALSE(l.model);
  EXPECT_TRUE(Contains(l.Errors(), ":3: <lua_controller>: lua_controller 'c' has no script")) << l.Errors();
}

// ---- placement

TEST(Placement, OverlappingRobotsAreRefusedWithBothLines) {
  std::string arena = FootBot("a", 0, 0, 0, "c") + "\n" + FootBot("b", 0.1, 0, 0, "c");
  Loaded l = LoadWith(Experiment(arena, kCtrl));
  EXPECT_FALSE(l.model);
  EXPECT_TRUE(Contains(l.Errors(), ":5: <foot-bot>: foot-bot 'b' overlaps foot-bot 'a' (line 4)")) << l.Errors();
}

TEST(Placement, ARobotInsideABoxOrACylinderIsRefused) {
  std::string arena = FootBot("a", 2, 2, 0, "c") + Box("wall", 2, 2, 1, 1, 0.5) + FootBot("b", -2, -2, 0, "c") +
                      "<cylinder id=\"cyl\" radius=\"0.2\" height=\"0.5\" movable=\"false\">"
                      "<body position=\"-2.2,-2,0\" orientation=\"0,0,0\"/></cylinder>" +
                      FootBot("free", 0, 0, 0, "c");
  Loaded l = LoadWith(Experiment(arena, kCtrl));
  EXPECT_FALSE(l.model);
  EXPECT_TRUE(Contains(l.Errors(), "foot-bot 'a' overlaps box 'wall'")) << l.Errors();
  EXPECT_TRUE(Contains(l.Errors(), "foot-bot 'b' overlaps cylinder 'cyl'")) << l.Errors();
  EXPECT_FALSE(Contains(l.Errors(), "'free'")) << l.Errors();
  // Touching is not overlapping (ARGoS needs penetration): 2 × 0.085036758 m apart.
  Loaded ok = LoadWith(Experiment(FootBot("a", 0, 0, 0, "c") + FootBot("b", 0.171, 0, 0, "c"), kCtrl));
  EXPECT_TRUE(ok.model) << ok.Errors();
}

TEST(Placement, ARobotOutsideTheArenaIsRefused) {
  Loaded l = LoadWith(Experiment(FootBot("far", 7, 0, 0, "c"), kCtrl));
  EXPECT_FALSE(l.model);
  EXPECT_TRUE(Contains(l.Errors(), "foot-bot 'far' at (7, 0) is outside the arena [-5, 5] x [-5, 5]")) << l.Errors();
}

TEST(Placement, DistributeAtFixedOverlappingPositionsIsAnErrorWithTheLine) {
  std::string arena = kDistribute;
  arena = Replace(arena, "method=\"uniform\" min=\"-4,-4,0\" max=\"4,4,0\"", "method=\"constant\" values=\"1,1,0\"");
  Loaded l = LoadWith(Experiment(arena, kCtrl));
  EXPECT_FALSE(l.model);
  EXPECT_TRUE(Contains(l.Errors(), "could not place 'fb1' without overlap after 101 attempts")) << l.Errors();

  std::string grid = kDistribute;
  grid = Replace(grid, "method=\"uniform\" min=\"-4,-4,0\" max=\"4,4,0\"",
                 "method=\"grid\" center=\"0,0,0\" distances=\"0.1,0.1,0\" layout=\"5,1,1\"");
  Loaded g = LoadWith(Experiment(grid, kCtrl));
  EXPECT_FALSE(g.model);
  EXPECT_TRUE(Contains(g.Errors(), "could not place 'fb1'")) << g.Errors();

  std::string outside = kDistribute;
  outside =
      Replace(outside, "method=\"uniform\" min=\"-4,-4,0\" max=\"4,4,0\"", "method=\"constant\" values=\"9,0,0\"");
  Loaded o = LoadWith(Experiment(outside, kCtrl));
  EXPECT_FALSE(o.model);
  EXPECT_TRUE(Contains(o.Errors(), "generated foot-bot 'fb0' at (9, 0) is outside the arena")) << o.Errors();
}

TEST(Placement, DistributeAtRandomRetriesUntilNoRobotOverlaps) {
  // 40 robots in a 1.6 m square: many draws collide and are retried.
  std::string arena = kDistribute;
  arena = Replace(arena, "min=\"-4,-4,0\" max=\"4,4,0\"", "min=\"-0.8,-0.8,0\" max=\"0.8,0.8,0\"");
  arena = Replace(arena, "quantity=\"5\" max_trials=\"100\"", "quantity=\"40\" max_trials=\"1000\"");
  Loaded l = LoadWith(Experiment(arena, kCtrl));
  ASSERT_TRUE(l.model) << l.Errors();
  const auto& robots = l.model->robots;
  ASSERT_EQ(robots.size(), 40u);
  for (size_t i = 0; i < robots.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      EXPECT_GE(std::hypot(robots[i].pose.x - robots[j].pose.x, robots[i].pose.y - robots[j].pose.y), 2 * 0.085036758)
          << robots[i].id << " and " << robots[j].id;
}

}  // namespace
}  // namespace essaim
