// The .argos loader: every error with file:line and element, --set, <distribute>.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

std::unique_ptr<Model> LoadText(const TempDir& dir, const std::string& xml, ErrorList* errors, LoadOptions opt = {}) {
  return LoadExperimentFile(dir.Write("x.argos", xml), opt, errors);
}

const char* kCtrl =
    "<lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/></actuators>"
    "<sensors/><params script=\"c.lua\" speed=\"10\"/></lua_controller>";

TEST(Loader, MinimalExperiment) {
  TempDir d;
  d.Write("c.lua", "function step() end");
  ErrorList e;
  auto m = LoadText(d, Experiment(FootBot("fb0", 1, 2, 90, "c"), kCtrl, 50), &e);
  ASSERT_TRUE(m) << e.Format();
  ASSERT_EQ(m->robots.size(), 1u);
  EXPECT_EQ(m->robots[0].id, "fb0");
  EXPECT_DOUBLE_EQ(m->robots[0].pose.x, 1);
  EXPECT_NEAR(m->robots[0].pose.yaw, kPi / 2, 1e-12);
  EXPECT_EQ(m->robots[0].params.at("speed"), "10");
  EXPECT_EQ(m->robots[0].params.at("script"), "c.lua");
  EXPECT_EQ(m->experiment.length_ticks, 50u);
  EXPECT_EQ(m->controllers[0].script, d.path() + "/c.lua");  // resolved beside the .argos
}

TEST(Loader, LengthIsTruncatedAsArgos) {
  TempDir d;
  d.Write("c.lua", "");
  ErrorList e;
  std::string xml = Experiment("", kCtrl);
  // 2.3 s at 100 ticks/s is 229.99999999999997 ticks: ARGoS runs 229.
  size_t a = xml.find("length=\""), b = xml.find('"', a + 8);
  xml.replace(a, b - a + 1, "length=\"2.3\"");
  a = xml.find("ticks_per_second=\""), b = xml.find('"', a + 18);
  xml.replace(a, b - a + 1, "ticks_per_second=\"100\"");
  auto m = LoadText(d, xml, &e);
  ASSERT_TRUE(m) << e.Format();
  EXPECT_EQ(m->experiment.length_ticks, 229u);
}

TEST(Loader, ReportsEveryErrorWithLineAndElement) {
  TempDir d;
  std::string xml =
      "<argos-configuration>\n"                                                                         // 1
      "  <framework><experiment ticks_per_second=\"ten\"/></framework>\n"                               // 2
      "  <controllers>\n"                                                                               // 3
      "    <lua_controller id=\"c\"><actuators><warp_drive implementation=\"default\"/></actuators>\n"  // 4
      "      <sensors/><params script=\"missing.lua\"/></lua_controller>\n"                             // 5
      "  </controllers>\n"                                                                              // 6
      "  <arena size=\"10,10\">\n"                                                                      // 7
      "    <teapot id=\"t\"/>\n"                                                                        // 8
      "    <box id=\"b\" size=\"1,1,1\" movable=\"true\"><body position=\"0,0,0\"/></box>\n"            // 9
      "  </arena>\n"
      "  <physics_engines><dynamics2d id=\"d\"/></physics_engines><media/>\n"
      "</argos-configuration>\n";
  ErrorList e;
  auto m = LoadText(d, xml, &e);
  EXPECT_FALSE(m);
  std::string all = e.Format();
  EXPECT_NE(all.find("x.argos:2: <experiment>: attribute 'ticks_per_second': 'ten' is not an integer"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find(":4: <warp_drive>: unknown actuator"), std::string::npos) << all;
  EXPECT_NE(all.find(":5: <params>: script 'missing.lua' not found"), std::string::npos) << all;
  EXPECT_NE(all.find(":7: <arena>: attribute 'size'"), std::string::npos) << all;
  EXPECT_NE(all.find(":8: <teapot>: unsupported entity"), std::string::npos) << all;
  EXPECT_NE(all.find(":9: <box>: missing required attribute 'mass'"), std::string::npos) << all;
  EXPECT_GE(e.Size(), 6u);
}

TEST(Loader, MalformedXmlNamesTheLine) {
  TempDir d;
  ErrorList e;
  EXPECT_FALSE(LoadText(d, "<argos-configuration>\n<framework>\n</arena>\n", &e));
  EXPECT_NE(e.Format().find("x.argos:2: malformed XML"), std::string::npos) << e.Format();
}

// tinyxml2's own text ("Error=XML_ERROR_MISMATCHED_ELEMENT ErrorID=14 (0xe) ...") is said
// for a person: the element, and what it lacks.
TEST(Loader, MalformedXmlSaysWhatIsWrongInWords) {
  TempDir d;
  const std::pair<const char*, const char*> cases[] = {
      {"<argos-configuration>\n<framework>\n  <output>\n</framework>\n</argos-configuration>\n",
       "x.argos:3: malformed XML: <output> opened on this line is not closed where it should be: its </output> is "
       "missing"},
      {"<argos-configuration>\n<framework x=\"1>\n</argos-configuration>\n",
       "x.argos:2: malformed XML: an attribute of <framework> cannot be read (write each as name=\"value\""},
      {"<argos-configuration>\n<!-- no end\n</argos-configuration>\n",
       "malformed XML: a comment '<!--' is not closed with '-->'"},
      {"", "the file is empty: an experiment is an XML file with an <argos-configuration> element"}};
  for (const auto& [text, message] : cases) {
    ErrorList e;
    EXPECT_FALSE(LoadText(d, text, &e));
    EXPECT_NE(e.Format().find(message), std::string::npos) << e.Format();
    EXPECT_EQ(e.Format().find("ErrorID"), std::string::npos) << e.Format();
  }
}

TEST(Loader, CppLoopFunctionsLibraryIsFoundBesideTheFileWithOrWithoutSo) {
  TempDir d;
  d.Write("c.lua", "");
  const std::string library = d.Write("libx.so", "");
  ErrorList e;
  auto m = LoadText(
      d, Experiment("", kCtrl, 10, 1, "<loop_functions library=\"libx\" label=\"x\"><p a=\"1\"/></loop_functions>"),
      &e);
  ASSERT_TRUE(m) << e.Format();
  EXPECT_EQ(m->loop_functions.library, library);
  EXPECT_EQ(m->loop_functions.label, "x");
  ASSERT_EQ(m->loop_functions.xml.children.size(), 1u);
  EXPECT_EQ(m->loop_functions.xml.children[0].attributes[0].second, "1");
}

// A C++ controller: the tag is the REGISTER_CONTROLLER label, library= found as ARGoS finds
// it (ARGOS_PLUGIN_PATH first, with and without .so), the element kept whole for Init.
TEST(Loader, CppControllerEntries) {
  TempDir d;
  d.Write("c.lua", "");
  std::filesystem::create_directory(d.path() + "/plugins");
  d.Write("plugins/libbot.so", "");
  d.Write("libother.so", "");
  setenv("ARGOS_PLUGIN_PATH", (d.path() + "/plugins").c_str(), 1);
  const std::string cpp =
      "<bot_controller id=\"b\" library=\"libbot\"><actuators/><sensors/>"
      "<params speed=\"3\"><wheel max=\"5\"/></params></bot_controller>"
      "<other_controller id=\"o\" library=\"libother\"><actuators/><sensors/><params/></other_controller>"
      "<label_alone id=\"l\"><actuators/><sensors/><params/></label_alone>";
  ErrorList e;
  auto m = LoadText(d, Experiment(FootBot("fb0", 1, 2, 90, "b"), kCtrl + cpp), &e);
  unsetenv("ARGOS_PLUGIN_PATH");
  ASSERT_TRUE(m) << e.Format();
  EXPECT_TRUE(e.Format().empty()) << e.Format();  // every attribute and child read
  const ControllerDef& b = m->controllers[1];
  EXPECT_TRUE(b.Cpp() && !m->controllers[0].Cpp());
  EXPECT_EQ(b.label, "bot_controller");
  EXPECT_EQ(b.library, d.path() + "/plugins/libbot.so");
  EXPECT_EQ(b.params.at("speed"), "3");
  ASSERT_EQ(b.xml.children.size(), 3u);
  EXPECT_EQ(b.xml.children[2].children[0].name, "wheel");
  EXPECT_EQ(m->controllers[2].library, d.path() + "/libother.so");  // beside the .argos file
  EXPECT_TRUE(m->controllers[3].Cpp() && m->controllers[3].library.empty());
  EXPECT_EQ(m->robots[0].controller, 1);
}

TEST(Loader, MisspeltLuaControllerIsNotTakenForALabel) {
  TempDir d;
  ErrorList e;
  EXPECT_FALSE(
      LoadText(d, Experiment("", "<lua_controler id=\"c\"><actuators/><sensors/><params/></lua_controler>"), &e));
  EXPECT_NE(e.Format().find("unknown controller type <lua_controler>; did you mean <lua_controller>?"),
            std::string::npos)
      << e.Format();
}

TEST(Loader, CppLoopFunctionsMissingLibraryOrLabelAreClearErrors) {
  TempDir d;
  d.Write("c.lua", "");
  ErrorList e;
  EXPECT_FALSE(LoadText(d, Experiment("", kCtrl, 10, 1, "<loop_functions library=\"libz\" label=\"x\"/>"), &e));
  // As ARGoS tries them: the working directory ("."), as written then with .so; essaim then
  // tries beside the .argos file.
  EXPECT_NE(e.Format().find("library 'libz' not found; tried ./libz, ./libz.so, " + d.path() + "/libz, " + d.path() +
                            "/libz.so (ARGOS_PLUGIN_PATH is not set)"),
            std::string::npos)
      << e.Format();
  ErrorList e2;
  d.Write("liby.so", "");
  EXPECT_FALSE(LoadText(d, Experiment("", kCtrl, 10, 1, "<loop_functions library=\"liby\"/>"), &e2));
  EXPECT_NE(e2.Format().find("C++ loop functions need label"), std::string::npos) << e2.Format();
}

TEST(Loader, UnsupportedDeviceIsNamed) {
  TempDir d;
  d.Write("c.lua", "");
  ErrorList e;
  std::string c =
      "<lua_controller id=\"c\"><actuators/><sensors><perspective_camera "
      "implementation=\"default\"/></sensors><params/></lua_controller>";
  EXPECT_FALSE(LoadText(d, Experiment("", c), &e));
  EXPECT_NE(e.Format().find("<perspective_camera>: unknown sensor"), std::string::npos) << e.Format();
}

// Numbers that size threads, loops or integer casts are bounded with a clear error, not UB
// (length="1e300" overflowed the cast to uint64_t; threads="100000" aborted in std::thread).
TEST(Loader, HugeNumbersAreClearErrors) {
  TempDir d;
  d.Write("c.lua", "");
  std::string xml = Experiment("", kCtrl);
  size_t at = xml.find("<experiment");
  LoadOptions o;
  o.overrides = {"framework.experiment.length=1e300"};
  ErrorList e1;
  EXPECT_FALSE(LoadText(d, xml, &e1, o));
  EXPECT_NE(e1.Format().find("length is too long"), std::string::npos) << e1.Format();
  EXPECT_NE(e1.Format().find("x.argos:"), std::string::npos) << e1.Format();
  o.overrides = {"framework.experiment.ticks_per_second=99999999999"};
  ErrorList e2;
  EXPECT_FALSE(LoadText(d, xml, &e2, o));
  EXPECT_NE(e2.Format().find("ticks_per_second must be between 1 and 1000000"), std::string::npos) << e2.Format();
  std::string with_system = xml;
  with_system.replace(at, 0, "<system threads=\"100000\"/>");
  ErrorList e3;
  EXPECT_FALSE(LoadText(d, with_system, &e3));
  EXPECT_NE(e3.Format().find("threads must be between 0 and 1024"), std::string::npos) << e3.Format();
}

TEST(Loader, SetOverridesAttributesByPath) {
  TempDir d;
  d.Write("c.lua", "");
  ErrorList e;
  LoadOptions o;
  o.overrides = {"controllers.c.params.speed=25", "framework.experiment.random_seed=99", "arena.fb0.rab_range=2"};
  auto m = LoadText(d, Experiment(FootBot("fb0", 0, 0, 0, "c"), kCtrl), &e, o);
  ASSERT_TRUE(m) << e.Format();
  EXPECT_EQ(m->robots[0].params.at("speed"), "25");
  EXPECT_EQ(m->experiment.seed, 99u);
  EXPECT_DOUBLE_EQ(m->robots[0].rab_range, 2);
  ErrorList bad;
  o.overrides = {"controllers.nope.params.speed=1"};
  EXPECT_FALSE(LoadText(d, Experiment("", kCtrl), &bad, o));
  EXPECT_NE(bad.Format().find("no element at 'controllers.nope'"), std::string::npos) << bad.Format();
}

TEST(Loader, PerRobotParamsReplaceTheControllers) {
  TempDir d;
  d.Write("c.lua", "");
  ErrorList e;
  std::string bot =
      "<foot-bot id=\"fb0\"><controller config=\"c\"><params script=\"c.lua\" mine=\"1\"/></controller></foot-bot>";
  auto m = LoadText(d, Experiment(bot, kCtrl), &e);
  ASSERT_TRUE(m) << e.Format();
  EXPECT_EQ(m->robots[0].params.count("speed"), 0u);
  EXPECT_EQ(m->robots[0].params.at("mine"), "1");
}

TEST(Loader, GridDistributeFollowsTheFormulaAndNamesIds) {
  TempDir d;
  d.Write("c.lua", "");
  ErrorList e;
  std::string dist =
      "<distribute><position method=\"grid\" center=\"1,2,0\" distances=\"0.5,0.4,0\" layout=\"3,2,1\"/>"
      "<orientation method=\"constant\" values=\"45,0,0\"/>"
      "<entity quantity=\"5\" max_trials=\"10\" base_num=\"7\"><foot-bot id=\"bot\"><controller "
      "config=\"c\"/></foot-bot></entity></distribute>";
  auto m = LoadText(d, Experiment(dist, kCtrl), &e);
  ASSERT_TRUE(m) << e.Format();
  ASSERT_EQ(m->robots.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(m->robots[k].id, "bot" + std::to_string(k + 7));
    // x = cx + (nx-1)dx/2 - (k mod nx)dx ; y = cy + (ny-1)dy/2 - ((k div nx) mod ny)dy
    EXPECT_NEAR(m->robots[k].pose.x, 1 + 0.5 - (k % 3) * 0.5, 1e-9);
    EXPECT_NEAR(m->robots[k].pose.y, 2 + 0.2 - ((k / 3) % 2) * 0.4, 1e-9);
    EXPECT_NEAR(m->robots[k].pose.yaw, kPi / 4, 1e-6);
  }
}

TEST(Loader, DistributeAvoidsOverlapsOrFailsClearly) {
  TempDir d;
  d.Write("c.lua", "");
  auto dist = [](int n) {
    return "<distribute><position method=\"uniform\" min=\"-0.5,-0.5,0\" max=\"0.5,0.5,0\"/>"
           "<orientation method=\"uniform\" min=\"0,0,0\" max=\"360,0,0\"/>"
           "<entity quantity=\"" +
           std::to_string(n) +
           "\" max_trials=\"200\"><foot-bot id=\"fb\"><controller config=\"c\"/></foot-bot></entity></distribute>";
  };
  ErrorList e;
  auto m = LoadText(d, Experiment(dist(10), kCtrl), &e);
  ASSERT_TRUE(m) << e.Format();
  for (size_t i = 0; i < m->robots.size(); ++i)
    for (size_t j = i + 1; j < m->robots.size(); ++j) {
      double dx = m->robots[i].pose.x - m->robots[j].pose.x, dy = m->robots[i].pose.y - m->robots[j].pose.y;
      EXPECT_GE(std::hypot(dx, dy), 2 * footbot::kRadius);
    }
  ErrorList full;
  EXPECT_FALSE(LoadText(d, Experiment(dist(500), kCtrl), &full));
  EXPECT_NE(full.Format().find("could not place"), std::string::npos) << full.Format();
}

TEST(Loader, SameSeedSamePlacementDifferentSeedDiffers) {
  TempDir d;
  d.Write("c.lua", "");
  std::string dist =
      "<distribute><position method=\"uniform\" min=\"-4,-4,0\" max=\"4,4,0\"/>"
      "<orientation method=\"gaussian\" mean=\"0,0,0\" std_dev=\"90,0,0\"/>"
      "<entity quantity=\"20\" max_trials=\"50\"><foot-bot id=\"fb\"><controller "
      "config=\"c\"/></foot-bot></entity></distribute>";
  ErrorList e;
  auto a = LoadText(d, Experiment(dist, kCtrl, 10, 5), &e);
  auto b = LoadText(d, Experiment(dist, kCtrl, 10, 5), &e);
  auto c = LoadText(d, Experiment(dist, kCtrl, 10, 6), &e);
  ASSERT_TRUE(a && b && c) << e.Format();
  EXPECT_EQ(a->robots[3].pose.x, b->robots[3].pose.x);
  EXPECT_NE(a->robots[3].pose.x, c->robots[3].pose.x);
  // ARGoS writes generated values with 6 significant digits.
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", a->robots[3].pose.x);
  EXPECT_EQ(std::strtod(buf, nullptr), a->robots[3].pose.x);
}

}  // namespace
}  // namespace essaim

namespace essaim {
namespace {
using namespace essaim::testing;

TEST(Loader, ReportsReferenceAndEntityErrors) {
  TempDir d;
  d.Write("c.lua", "");
  std::string ctrl =
      "<lua_controller id=\"c\"><actuators/><sensors>"
      "<footbot_base_ground implementation=\"rot_z_only\"/>"
      "<range_and_bearing implementation=\"medium\" medium=\"radio\"/>"
      "</sensors><params script=\"c.lua\"/></lua_controller>";
  std::string arena =
      "<foot-bot id=\"a\"><controller config=\"nope\"/></foot-bot>"
      "<foot-bot id=\"a\"><controller config=\"c\"/><battery discharge_model=\"solar\"/></foot-bot>";
  std::string xml = Experiment(arena, ctrl);
  size_t p = xml.find("<dynamics2d");
  xml.insert(p, "<pointmass3d id=\"pm\"/>");
  ErrorList e;
  auto m = LoadExperimentFile(d.Write("x.argos", xml), {}, &e);
  EXPECT_FALSE(m);
  std::string all = e.Format();
  EXPECT_NE(all.find("<pointmass3d>: unsupported physics engine"), std::string::npos) << all;
  EXPECT_NE(all.find("<foot-bot>: duplicate id 'a'"), std::string::npos) << all;
  EXPECT_NE(all.find("<battery>: discharge_model must be time, motion or time_motion"), std::string::npos) << all;
  EXPECT_NE(all.find("<controller>: no controller with id 'nope'"), std::string::npos) << all;
  EXPECT_NE(all.find("medium 'radio' is not declared in <media>"), std::string::npos) << all;
  EXPECT_NE(all.find("ground sensors need a <floor>"), std::string::npos) << all;
}

TEST(Loader, MissingFloorImageAndExhaustedGridAreErrors) {
  TempDir d;
  d.Write("c.lua", "");
  std::string arena =
      "<floor id=\"f\" source=\"image\" path=\"nowhere.png\"/>"
      "<distribute><position method=\"grid\" center=\"0,0,0\" distances=\"1,1,0\" layout=\"2,1,1\"/>"
      "<orientation method=\"constant\" values=\"0,0,0\"/>"
      "<entity quantity=\"3\" max_trials=\"5\"><foot-bot id=\"fb\"><controller "
      "config=\"c\"/></foot-bot></entity></distribute>";
  ErrorList e;
  EXPECT_FALSE(LoadExperimentFile(d.Write("x.argos", Experiment(arena, kCtrl)), {}, &e));
  std::string all = e.Format();
  EXPECT_NE(all.find("<floor>: floor image 'nowhere.png' not found"), std::string::npos) << all;
  EXPECT_NE(all.find("grid exhausted"), std::string::npos) << all;
}

// A loop-function floor is rasterised whole: a 10^6 m arena at 50 pixels/m used to end in
// std::bad_alloc (abort) when the world was built.
TEST(Loader, LoopFunctionFloorTooLargeToRasteriseIsAnError) {
  TempDir d;
  d.Write("c.lua", "function step() end");
  d.Write("loop.lua", "function floor_color(x, y) return 0, 0, 0 end");
  std::string xml = Experiment("<floor id=\"f\" source=\"loop_functions\" pixels_per_meter=\"50\"/>", kCtrl, 10, 1,
                               "<loop_functions script=\"loop.lua\"/>");
  const std::string size = "size=\"";
  size_t a = xml.find(size, xml.find("<arena")) + size.size();
  xml.replace(a, xml.find('"', a) - a, "1000000, 100, 1");
  ErrorList e;
  EXPECT_FALSE(LoadText(d, xml, &e));
  EXPECT_NE(e.Format().find("<floor>: the floor would be 50000000 x 5000 pixels"), std::string::npos) << e.Format();
}

// Found by the CI fuzz pass (UBSan): layout="1e80,1,1" overflowed the double-to-int cast.
TEST(Loader, GridLayoutOutOfIntRangeIsAnError) {
  TempDir d;
  d.Write("c.lua", "function step() end");
  for (const char* layout : {"1e80,1,1", "-1e80,1,1", "1,0,1"}) {
    std::string arena =
        std::string("<distribute><position method=\"grid\" center=\"0,0,0\" distances=\"1,1,0\" layout=\"") + layout +
        "\"/><orientation method=\"constant\" values=\"0,0,0\"/>"
        "<entity quantity=\"1\"><foot-bot id=\"d\"><controller config=\"c\"/></foot-bot></entity></distribute>";
    ErrorList e;
    EXPECT_FALSE(LoadText(d, Experiment(arena, kCtrl), &e)) << layout;
    EXPECT_NE(e.Format().find("<position>: layout components must be > 0 (and at most 1000000)"), std::string::npos)
        << e.Format();
  }
}

// Found by fuzz_argos: Box2D keeps floats and asserts they are finite, so a position of
// 1e39 m or an orientation of 1e300 degrees aborted the process when the world was built.
TEST(Loader, FarPositionsAreErrorsAndHugeAnglesAreReduced) {
  TempDir d;
  d.Write("c.lua", "function step() end");
  ErrorList e;
  std::string arena =
      FootBot("far", 1e39, 0, 0, "c") +
      "<distribute><position method=\"uniform\" min=\"0,0,0\" max=\"1e300,1,0\"/>"
      "<orientation method=\"constant\" values=\"0,0,0\"/>"
      "<entity quantity=\"1\"><foot-bot id=\"d\"><controller config=\"c\"/></foot-bot></entity></distribute>";
  EXPECT_FALSE(LoadText(d, Experiment(arena, kCtrl), &e));
  std::string all = e.Format();
  EXPECT_NE(all.find("<body>: position beyond 1e6 m from the origin"), std::string::npos) << all;
  EXPECT_NE(all.find("<position>: position beyond 1e6 m from the origin"), std::string::npos) << all;

  ErrorList e2;
  auto m = LoadText(
      d,
      Experiment(FootBot("a", 0, 0, 1e300, "c") + FootBot("b", 1, 0, 450, "c") + FootBot("c", -1, 0, 90, "c"), kCtrl),
      &e2);
  ASSERT_TRUE(m) << e2.Format();
  EXPECT_DOUBLE_EQ(m->robots[0].pose.yaw, DegToRad(std::fmod(1e300, 360.0)));
  EXPECT_DOUBLE_EQ(m->robots[1].pose.yaw, DegToRad(90));
  EXPECT_DOUBLE_EQ(m->robots[2].pose.yaw, DegToRad(90));
  SimOptions opt;
  std::string error;
  EXPECT_TRUE(World::Create(*m, opt, &error)) << error;  // used to abort in b2Body's constructor
}

}  // namespace
}  // namespace essaim
