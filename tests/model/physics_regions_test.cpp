// Physics regions as the loader reads them: ARGoS's <boundaries> of several engines, and
// one engine's regions="K" strips; bad boundaries are errors naming the file, line and element.
#include "model/physics_regions.h"

#include <gtest/gtest.h>

#include "core/strings.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

const std::vector<Vec2> kUnitSquare = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

TEST(PhysicsRegions, PolygonContainsIsHalfOpenOnSharedEdges) {
  EXPECT_TRUE(PolygonContains(kUnitSquare, {0.5, 0.5}));
  EXPECT_FALSE(PolygonContains(kUnitSquare, {1.5, 0.5}));
  // The edge x = 1 is shared with the square to its right: exactly one of them holds it.
  const std::vector<Vec2> right = {{1, 0}, {2, 0}, {2, 1}, {1, 1}};
  EXPECT_FALSE(PolygonContains(kUnitSquare, {1, 0.5}));
  EXPECT_TRUE(PolygonContains(right, {1, 0.5}));
  // A concave L: the notch is outside.
  const std::vector<Vec2> l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_TRUE(PolygonContains(l, {0.5, 1.5}));
  EXPECT_FALSE(PolygonContains(l, {1.5, 1.5}));
}

TEST(PhysicsRegions, RegionOfTakesTheFirstInDeclarationOrder) {
  PhysicsRegionDef a, b, all;
  a.sides = kUnitSquare;
  b.sides = {{1, 0}, {2, 0}, {2, 1}, {1, 1}};
  EXPECT_EQ(RegionOf({a, b}, {0.5, 0.5}, -1), 0);
  EXPECT_EQ(RegionOf({a, b}, {1.5, 0.5}, -1), 1);
  EXPECT_EQ(RegionOf({a, b}, {5, 5}, 7), 7);     // in none: the fallback
  EXPECT_EQ(RegionOf({a, all}, {5, 5}, -1), 1);  // an unbounded engine holds everything
  EXPECT_EQ(TwiceSignedArea(kUnitSquare), 2);
}

TEST(PhysicsRegions, RegionProblemNamesWhatIsWrong) {
  PhysicsRegionDef r;
  r.top = 1;
  r.sides = kUnitSquare;
  EXPECT_EQ(RegionProblem(r), "");
  r.sides = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};  // clockwise
  EXPECT_NE(RegionProblem(r).find("counter-clockwise"), std::string::npos);
  r.sides = {{0, 0}, {1, 0}};
  EXPECT_NE(RegionProblem(r).find("at least 3 vertices, found 2"), std::string::npos);
  r.sides = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};  // a bow tie
  EXPECT_NE(RegionProblem(r).find("cross"), std::string::npos);
  r.sides = kUnitSquare;
  r.top = 0;
  EXPECT_NE(RegionProblem(r).find("below"), std::string::npos);
}

TEST(PhysicsRegions, ArenaStripsCoverEverythingAlongTheLongerSide) {
  ArenaDef arena;
  arena.size = Vec3(8, 4, 1);
  const std::vector<PhysicsRegionDef> s = ArenaStrips(arena, "d", 4);
  ASSERT_EQ(s.size(), 4u);
  EXPECT_EQ(s[2].id, "d_2");
  EXPECT_EQ(RegionOf(s, {-3.5, 0}, -1), 0);
  EXPECT_EQ(RegionOf(s, {-2, 1}, -1), 1);  // on the boundary between strips 0 and 1
  EXPECT_EQ(RegionOf(s, {0.5, -1.9}, -1), 2);
  EXPECT_EQ(RegionOf(s, {1e5, 1e5}, -1), 3);  // far outside the arena: the last strip
  EXPECT_EQ(RegionOf(s, {-1e5, 0}, -1), 0);
  for (const PhysicsRegionDef& r : s) EXPECT_EQ(RegionProblem(r), "");
}

std::string Engine(const std::string& id, const std::string& vertices,
                   const std::string& heights = "<top height=\"1\"/><bottom height=\"0\"/>") {
  return "<dynamics2d id=\"" + id + "\" iterations=\"10\"><boundaries>" + heights + "<sides>" + vertices +
         "</sides></boundaries></dynamics2d>";
}

std::string Vertices(const std::vector<Vec2>& v) {
  std::string out;
  for (const Vec2& p : v) out += "<vertex point=\"" + FormatDouble(p.x()) + "," + FormatDouble(p.y()) + "\"/>";
  return out;
}

const std::string kWest = Vertices({{-5, -5}, {0, -5}, {0, 5}, {-5, 5}});
const std::string kEast = Vertices({{0, -5}, {5, -5}, {5, 5}, {0, 5}});

std::string WithEngines(const std::string& engines, const std::string& arena = "") {
  std::string xml = Experiment(arena, WheelsController("c", "idle.lua"));
  const std::string one = "<dynamics2d id=\"dyn2d\" iterations=\"10\"/>";
  xml.replace(xml.find(one), one.size(), engines);
  return xml;
}

Scene LoadEngines(const std::string& engines, const std::string& arena = "") {
  TempDir d;
  d.Write("idle.lua", "function step() end");
  return Load(d, WithEngines(engines, arena));
}

TEST(PhysicsRegionsLoader, TwoEnginesMakeTwoRegions) {
  Scene s = LoadEngines(Engine("west", kWest) + Engine("east", kEast),
                        FootBot("a", -1, 0, 0, "c") + FootBot("b", 1, 0, 0, "c"));
  ASSERT_TRUE(s.ok()) << s.error;
  const PhysicsDef& p = s.model->physics;
  ASSERT_EQ(p.regions.size(), 2u);
  EXPECT_EQ(p.regions[0].id, "west");
  EXPECT_EQ(p.regions[1].id, "east");
  ASSERT_EQ(p.regions[1].sides.size(), 4u);
  EXPECT_EQ(p.regions[1].sides[1], Vec2(5, -5));
  EXPECT_EQ(p.regions[1].top, 1);
  EXPECT_EQ(s.world->physics.RegionCount(), 2);
  EXPECT_EQ(s.world->physics.RobotRegion(0), 0);
  EXPECT_EQ(s.world->physics.RobotRegion(1), 1);
}

TEST(PhysicsRegionsLoader, OneEngineIsOneWorld) {
  Scene s = LoadEngines("<dynamics2d id=\"dyn2d\" iterations=\"10\"/>", FootBot("a", 1, 0, 0, "c"));
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_TRUE(s.model->physics.regions.empty());
  EXPECT_EQ(s.world->physics.RegionCount(), 1);
}

TEST(PhysicsRegionsLoader, RegionsAttributeSplitsTheArenaIntoStrips) {
  Scene s = LoadEngines("<dynamics2d id=\"dyn2d\" iterations=\"10\" regions=\"3\"/>", FootBot("a", 4, 0, 0, "c"));
  ASSERT_TRUE(s.ok()) << s.error;
  ASSERT_EQ(s.model->physics.regions.size(), 3u);
  EXPECT_EQ(s.model->physics.regions[0].id, "dyn2d_0");
  EXPECT_EQ(s.world->physics.RobotRegion(0), 2);
}

// The error names the file, the line and the element, and says what is wrong.
void ExpectError(const std::string& engines, const std::string& arena, const std::string& element,
                 const std::string& message) {
  Scene s = LoadEngines(engines, arena);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error.find("experiment.argos:"), std::string::npos) << s.error;
  EXPECT_NE(s.error.find("<" + element + ">"), std::string::npos) << s.error;
  EXPECT_NE(s.error.find(message), std::string::npos) << s.error;
}

TEST(PhysicsRegionsLoader, BadBoundariesAreErrors) {
  const std::string clockwise = Vertices({{-5, -5}, {-5, 5}, {0, 5}, {0, -5}});
  ExpectError(Engine("west", clockwise) + Engine("east", kEast), "", "sides", "counter-clockwise");
  ExpectError(Engine("west", Vertices({{0, 0}, {1, 0}})) + Engine("east", kEast), "", "sides", "at least 3 vertices");
  ExpectError(Engine("west", "<vertex point=\"1,x\"/>") + Engine("east", kEast), "", "vertex",
              "must be two comma-separated numbers");
  ExpectError(Engine("west", kWest, "<top height=\"1\"/>") + Engine("east", kEast), "", "boundaries",
              "needs <top height>, <bottom height> and <sides>");
  ExpectError(Engine("west", kWest) + Engine("west", kEast), "", "dynamics2d", "duplicate engine id 'west'");
  ExpectError(Engine("west", kWest) + Engine("east", Vertices({{0, -5}, {4, -5}, {4, 5}, {0, 5}})),
              FootBot("far", 4.5, 0, 0, "c"), "dynamics2d", "foot-bot 'far' at (4.5, 0) lies in no physics engine");
  ExpectError("<dynamics2d id=\"d\" regions=\"0\"/>", "", "dynamics2d", "regions must be between 1 and");
  ExpectError(Engine("west", kWest) + "<dynamics2d id=\"e\" regions=\"2\"/>", "", "dynamics2d",
              "not with several engines");
}

}  // namespace
}  // namespace essaim
