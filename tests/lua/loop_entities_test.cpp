// Loop functions' reach (docs/loop-functions.md): entities by kind, poses, LEDs,
// lights, entities added and removed at run time as every sensor sees them, a
// controller's Lua globals, <loop_functions> children, the legacy <led position=...>.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "core/json.h"
#include "output/recording.h"
#include "sim/run_end.h"
#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

// Media "leds"; robots with a camera, LEDs and a light sensor; loop.lua as loop functions.
std::string SensingController(const std::string& script) {
  return "<lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/>"
         "<leds implementation=\"default\" medium=\"leds\"/></actuators><sensors>"
         "<colored_blob_omnidirectional_camera implementation=\"rot_z_only\" medium=\"leds\"/>"
         "<footbot_light implementation=\"rot_z_only\" show_rays=\"false\"/>"
         "<positioning implementation=\"default\"/></sensors><params script=\"" +
         script + "\"/></lua_controller>";
}

std::string LoopExperiment(const std::string& arena, const std::string& controllers,
                           const std::string& loop_children = "", int threads = 0) {
  std::string xml = Experiment(arena, controllers, 1000, 3,
                               "<loop_functions script=\"loop.lua\">" + loop_children + "</loop_functions>\n");
  xml.replace(xml.find("<media/>"), 8, "<media><led id=\"leds\"/></media>");
  if (threads > 0)
    xml.replace(xml.find("<experiment "), 12, "<system threads=\"" + std::to_string(threads) + "\"/><experiment ");
  return xml;
}

std::string Cylinder(const std::string& id, double x, double y, bool movable, const std::string& leds = "") {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "<cylinder id=\"%s\" radius=\"0.1\" height=\"0.2\" movable=\"%s\" %s><body position=\"%g,%g,0\" "
                "orientation=\"0,0,0\"/>%s</cylinder>",
                id.c_str(), movable ? "true" : "false", movable ? "mass=\"0.1\"" : "", x, y, leds.c_str());
  return buf;
}

constexpr char kStill[] =
    "function init() robot.colored_blob_omnidirectional_camera.enable() end\nfunction step() end\n";

std::string Fails(const std::string& loop, const std::string& arena = "") {
  TempDir d;
  d.Write("c.lua", kStill);
  d.Write("loop.lua", loop);
  Scene s = Load(d, LoopExperiment(FootBot("fb0", 0, 0, 0, "c") + arena, SensingController("c.lua")));
  if (!s.ok()) return s.error;
  if (!s.world->failure.empty()) return s.world->failure;  // init() failed: never stepped
  for (int i = 0; i < 3; ++i)
    if (Step(*s.world) == StepStatus::Failed) return s.world->failure;
  return "";
}

TEST(LoopEntities, EntitiesByKindInCreationOrderWithStableHandles) {
  TempDir d;
  d.Write("c.lua", kStill);
  d.Write("loop.lua", R"(
function init()
  local all = experiment.entities()
  local ids = {}
  for _, e in ipairs(all) do ids[#ids + 1] = e.kind .. ":" .. e.id end
  order = table.concat(ids, ",")
  assert(experiment.entities("foot-bot")[2] == experiment.robots[2], "same handle objects")
  assert(experiment.entities("box")[1].index == nil and experiment.robots[2].index == 2)
  local c = experiment.entities("cylinder")[1]
  local x, y, z = c:position()
  assert(x == 1 and y == 2 and z == 0, x .. " " .. y)
  assert(c:movable() and not experiment.entities("box")[1]:movable() and experiment.robots[1]:movable())
  assert(math.abs(experiment.entities("box")[1]:heading() - math.pi / 2) < 1e-6)
  local l = experiment.entities("light")[1]
  assert(select(3, l:position()) == 0.5 and l:intensity() == 2)
  local r, g, b = l:color(); assert(r == 255 and g == 255 and b == 0)
  -- static ones move before the first step
  experiment.entities("box")[1]:set_pose(-2, -2, 0)
end
function post_step()
  local c = experiment.entities("cylinder")[1]
  c:set_pose(0.5, -1)  -- yaw kept
  local x, y = c:position()
  moved = x == 0.5 and y == -1
end
function post_experiment() return {order = order, moved = moved} end
)");
  std::string arena = FootBot("fb0", 0, 0, 0, "c") + FootBot("fb1", 3, 0, 0, "c") + Cylinder("cyl", 1, 2, true) +
                      "<box id=\"bx\" size=\"0.2,0.2,0.2\" movable=\"false\"><body position=\"-1,1,0\" "
                      "orientation=\"90,0,0\"/></box>"
                      "<light id=\"lt\" position=\"2,2,0.5\" orientation=\"0,0,0\" color=\"yellow\" intensity=\"2\" "
                      "medium=\"leds\"/>";
  Scene s = Load(d, LoopExperiment(arena, SensingController("c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  EXPECT_NEAR(s.world->physics.ObstaclePose(1).x, -2, 1e-6);  // the box, moved in init
  Step(*s.world);
  Value metrics_tree;
  bool has = false;
  std::string err;
  ASSERT_TRUE(FinishRun(*s.world, &metrics_tree, &has, &err)) << err;
  Json metrics = ToJson(metrics_tree);
  EXPECT_EQ(metrics["order"], "foot-bot:fb0,foot-bot:fb1,cylinder:cyl,box:bx,light:lt");
  EXPECT_EQ(metrics["moved"], true);
}

TEST(LoopEntities, TheCameraSeesARecolouredLedFromTheNextSense) {
  TempDir d;
  d.Write("c.lua", kStill);
  d.Write("loop.lua", R"(
function init()  -- an added cylinder's LED is seen too
  experiment.add_entity("cylinder", {position = {0, 0.5}, radius = 0.05, height = 0.2, medium = "leds",
                                     leds = {{offset = {0, 0, 0.2}, anchor = "origin", color = "green"}}})
end
function pre_step()
  local c = experiment.entities("cylinder")[1]
  if experiment.tick == 2 then c:set_led_color("blue") end
  if experiment.tick == 3 then c:set_led_color(2, 0, 255, 0) end
  if experiment.tick == 4 then
    local r, g, b = c:led_color(2)
    assert(c:led_count() == 2 and r == 0 and g == 255 and b == 0)
  end
end
)");
  const std::string leds =
      "<leds medium=\"leds\"><led offset=\"0,0,0.2\" anchor=\"origin\" color=\"red\"/>"
      "<led offset=\"0.05,0,0.2\" anchor=\"origin\" color=\"red\"/></leds>";
  Scene s = Load(d, LoopExperiment(FootBot("fb0", 0, 0, 0, "c") + Cylinder("cyl", 0.5, 0, false, leds),
                                   SensingController("c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  auto colours = [&] {
    std::string out;
    for (const Blob& b : s.world->robots[0].rd.blobs)
      out += std::to_string(b.color.r) + "," + std::to_string(b.color.g) + "," + std::to_string(b.color.b) + ";";
    return out;
  };
  Step(*s.world);
  EXPECT_EQ(colours(), "255,0,0;255,0,0;0,255,0;");
  Step(*s.world);  // recoloured in this tick's pre_step: seen by this tick's sense
  EXPECT_EQ(colours(), "0,0,255;0,0,255;0,255,0;");
  Step(*s.world);
  EXPECT_EQ(colours(), "0,0,255;0,255,0;0,255,0;");
  EXPECT_EQ(Step(*s.world), StepStatus::Running) << s.world->failure;
}

TEST(LoopEntities, TheLightSensorSeesAnAddedLightAndARemovedCylinderStopsBlockingIt) {
  TempDir d;
  d.Write("c.lua", kStill);
  d.Write("loop.lua", R"(
function init()
  light = experiment.add_entity("light", {id = "sun", position = {1, 0, 0}, color = "yellow", intensity = 1,
                                          medium = "leds"})
  wall = experiment.add_entity("cylinder", {position = {0.5, 0, 0}, radius = 0.05, height = 0.5})
  assert(wall.id == "cylinder_2" and wall.kind == "cylinder" and #experiment.entities() == 3, wall.id)
end
function pre_step()
  if experiment.tick == 2 then experiment.remove_entity(wall) end
  if experiment.tick == 3 then light:set_intensity(0) end
end
)");
  Scene s = Load(d, LoopExperiment(FootBot("fb0", 0, 0, 0, "c"), SensingController("c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  auto light_sum = [&] {
    const double* l = s.world->robots[0].rd.light;
    return std::accumulate(l, l + 24, 0.0);
  };
  Step(*s.world);
  EXPECT_EQ(light_sum(), 0.0);  // the added cylinder stands between the robot and the light
  Step(*s.world);
  EXPECT_GT(light_sum(), 0.1);  // removed in pre_step: the ray reaches the light
  Step(*s.world);
  EXPECT_EQ(light_sum(), 0.0);  // intensity 0
  EXPECT_EQ(s.world->physics.ObstacleCount(), 0);
}

TEST(LoopEntities, AddedObstaclesArePhysicalAndRecorded) {
  TempDir d;
  d.Write("c.lua", "function step() robot.wheels.set_velocity(20, 20) end");
  d.Write("loop.lua", R"(
function init()
  box = experiment.add_entity("box", {id = "crate", position = {0.5, 0}, size = {0.1, 0.6, 0.2},
                                      movable = true, mass = 5, medium = "leds",
                                      leds = {{offset = {0, 0, 0.2}, color = {255, 0, 0}}}})
  gone = experiment.add_entity("cylinder", {id = "gone", position = {-2, -2}, radius = 0.1, height = 0.1,
                                            movable = true, mass = 1})
end
function post_step()
  if experiment.tick == 5 then experiment.remove_entity(gone) end
  if experiment.tick == 10 then box:set_led_color("blue") end
  if experiment.tick == 12 then  -- added during the run: a slot of its own in the frames
    experiment.add_entity("box", {id = "late", position = {-1, -1}, size = {0.2, 0.2, 0.2}})
    experiment.add_entity("light", {id = "lamp", position = {1, 1, 0.5}, color = "yellow", medium = "leds"})
  end
end
)");
  Scene s = Load(d, LoopExperiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RecordingWriter rec;
  std::string err;
  ASSERT_TRUE(rec.Open(d.path() + "/rec.bin", *s.world, 1, &err)) << err;
  for (int i = 0; i < 30; ++i) {
    ASSERT_EQ(Step(*s.world), StepStatus::Running) << s.world->failure;
    rec.Record(*s.world);
  }
  ASSERT_TRUE(rec.Finish(*s.world, &err)) << err;
  // The robot drove into the crate and pushed it.
  const double crate = s.world->physics.ObstaclePose(0).x;
  EXPECT_GT(crate, 0.55);
  EXPECT_LT(s.world->physics.RobotPose(0).x, crate - 0.05 - 0.08);  // behind it, not through it
  Recording r;
  ASSERT_TRUE(Recording::Read(d.path() + "/rec.bin", &r, &err)) << err;
  ASSERT_EQ(r.scene().obstacles.size(), 3u);  // crate, gone, and late (added at tick 12)
  EXPECT_EQ(r.scene().obstacles[0].id, "crate");
  EXPECT_TRUE(r.MovablePresent(4, 1));
  EXPECT_FALSE(r.MovablePresent(5, 1));
  EXPECT_TRUE(r.MovablePresent(5, 0));
  EXPECT_EQ(r.scene().obstacles[0].led.r, 255);  // as added
  EXPECT_EQ(r.MovableLed(9, 0).r, 255);
  EXPECT_EQ(r.MovableLed(10, 0).b, 255);  // recoloured in post_step of tick 10
  EXPECT_EQ(r.MovableLed(10, 0).r, 0);
  ASSERT_EQ(r.scene().movable.size(), 3u);
  EXPECT_EQ(r.scene().obstacles[2].id, "late");
  EXPECT_FALSE(r.scene().obstacles[2].movable);
  EXPECT_FALSE(r.MovablePresent(11, 2));
  EXPECT_TRUE(r.MovablePresent(12, 2));
  EXPECT_NEAR(r.Movable(30, 2).x, -1, 1e-3);
  EXPECT_EQ(r.FrameCount(), 31u);
  EXPECT_NEAR(r.Movable(30, 0).x, s.world->physics.ObstaclePose(0).x, 1e-3);  // earlier slots intact
  ASSERT_EQ(r.scene().lights.size(), 1u);
  EXPECT_EQ(r.scene().lights[0].id, "lamp");
}

TEST(LoopEntities, AddedFootBotsAreRecorded) {
  TempDir d;
  d.Write("c.lua", "function step() robot.wheels.set_velocity(10, 12) end");
  d.Write("loop.lua", R"(
function init()  -- before the recording opens: in its scene from the start
  experiment.add_entity("foot-bot", {id = "early", controller = "c", position = {0, 1}, orientation = 90})
end
function post_step()
  if experiment.tick == 7 then experiment.add_entity("box", {id = "crate", position = {-1, -1}, size = {0.2, 0.2, 0.2}}) end
  if experiment.tick == 12 then
    experiment.add_entity("foot-bot", {id = "late", controller = "c", position = {1, -1}, orientation = 180})
  end
end
)");
  Scene s = Load(d, LoopExperiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  RecordingWriter rec;
  std::string err;
  ASSERT_TRUE(rec.Open(d.path() + "/rec.bin", *s.world, 1, &err)) << err;
  std::vector<std::vector<Pose2>> physics(1);  // per tick, per robot, as the physics had them
  for (int i = 0; i < 2; ++i) physics[0].push_back(s.world->physics.RobotPose(i));
  for (int t = 1; t <= 30; ++t) {
    ASSERT_EQ(Step(*s.world), StepStatus::Running) << s.world->failure;
    rec.Record(*s.world);
    physics.emplace_back();
    for (int i = 0; i < s.world->physics.RobotCount(); ++i) physics.back().push_back(s.world->physics.RobotPose(i));
  }
  ASSERT_TRUE(rec.Finish(*s.world, &err)) << err;
  Recording r;
  ASSERT_TRUE(Recording::Read(d.path() + "/rec.bin", &r, &err)) << err;
  ASSERT_EQ(r.scene().robot_ids, (std::vector<std::string>{"fb0", "early", "late"}));
  ASSERT_EQ(r.FrameCount(), 31u);
  EXPECT_EQ(r.FrameBytes(), 4u + 3 * 10u + 8u);  // three robots, one late box
  for (size_t k = 0; k < r.FrameCount(); ++k) {
    SCOPED_TRACE("frame " + std::to_string(k));
    for (size_t i = 0; i < 3; ++i) {
      const RecordedRobot robot = r.Robot(k, i);
      ASSERT_EQ(robot.present, i < 2 || k >= 12) << r.scene().robot_ids[i];
      EXPECT_EQ(robot.alive, robot.present);
      if (!robot.present) continue;
      EXPECT_NEAR(robot.x, physics[k][i].x, 0.5e-3 + 1e-9) << r.scene().robot_ids[i];
      EXPECT_NEAR(robot.y, physics[k][i].y, 0.5e-3 + 1e-9) << r.scene().robot_ids[i];
    }
    EXPECT_EQ(r.MovablePresent(k, 0), k >= 7);  // the box's slot after the late robot's
  }
  EXPECT_NEAR(r.Robot(12, 2).x, 1, 1e-3);                                   // where it was added
  EXPECT_GT(std::hypot(r.Robot(30, 2).x - 1, r.Robot(30, 2).y + 1), 0.05);  // and it drove on
  EXPECT_NEAR(r.Movable(30, 0).x, -1, 1e-3);
}

TEST(LoopEntities, RemovingAHeldCylinderReleasesTheGripAndShiftsNoOtherHold) {
  TempDir d;
  d.Write("c.lua",
          "function init() robot.gripper.lock_positive() robot.wheels.set_velocity(5, 5) end\n"
          "function step() end");
  d.Write("loop.lua", R"(
function post_step()
  if experiment.tick == 40 then experiment.remove_entity(experiment.entities("cylinder")[1]) end
end
)");
  const std::string ctrl =
      "<lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/>"
      "<footbot_gripper implementation=\"default\"/></actuators><sensors/><params script=\"c.lua\"/></lua_controller>";
  // Robot 0 grips cylinder "a" (index 0), robot 1 grips "b" (index 1, then 0 once "a" is gone).
  Scene s = Load(d, LoopExperiment(FootBot("fb0", 0, 0, 0, "c") + FootBot("fb1", 0, 1, 0, "c") +
                                       Cylinder("a", 0.3, 0, true) + Cylinder("b", 0.3, 1, true),
                                   ctrl));
  ASSERT_TRUE(s.ok()) << s.error;
  RunTicks(*s.world, 39);
  ASSERT_TRUE(s.world->physics.Gripped(0).Holding());
  ASSERT_EQ(s.world->physics.Gripped(1).index, 1);
  Step(*s.world);  // post_step of tick 40 removes "a"
  EXPECT_EQ(s.world->physics.ObstacleCount(), 1);
  EXPECT_FALSE(s.world->physics.Gripped(0).Holding());
  EXPECT_EQ(s.world->physics.Gripped(1).index, 0);
  for (int i = 0; i < 20; ++i) ASSERT_EQ(Step(*s.world), StepStatus::Running) << s.world->failure;
  EXPECT_TRUE(s.world->physics.Gripped(1).Holding());
  EXPECT_NEAR(s.world->physics.ObstaclePose(0).y, 1, 0.01);  // "b", still carried by fb1
  EXPECT_GT(s.world->physics.ObstaclePose(0).x, 0.3);
}

TEST(LoopEntities, LuaGlobalCopiesNestedTablesAndCyclesAndSetLuaGlobalWrites) {
  TempDir d;
  d.Write("c.lua", R"(
state = {count = 3, name = "fb", nested = {list = {1, 2.5, "x"}, flag = true}, fn = function() end}
state.self = state
found = 0
function step() found = found + (bonus or 0) end
)");
  d.Write("loop.lua", R"(
function post_step()
  local r = experiment.robots[1]
  local s = r:lua_global("state")
  assert(s.count == 3 and math.type(s.count) == "integer" and s.name == "fb")
  assert(s.nested.list[2] == 2.5 and s.nested.list[3] == "x" and s.nested.flag == true)
  assert(s.fn == nil and s.self == s, "cycle kept, function dropped")
  s.count = 99
  assert(r:lua_global("state").count == 3, "a copy, not a view")
  assert(r:lua_global("nothing") == nil)
  r:set_lua_global("bonus", 2)
  r:set_lua_global("cfg", {a = {b = "c"}})
  total = r:lua_global("found")
end
function post_experiment() return {total = total, cfg = experiment.robots[1]:lua_global("cfg").a.b} end
)");
  Scene s = Load(d, LoopExperiment(FootBot("fb0", 0, 0, 0, "c"), WheelsController("c", "c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  for (int i = 0; i < 3; ++i) ASSERT_EQ(Step(*s.world), StepStatus::Running) << s.world->failure;
  ASSERT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
  Value metrics_tree;
  bool has = false;
  std::string err;
  ASSERT_TRUE(FinishRun(*s.world, &metrics_tree, &has, &err)) << err;
  Json metrics = ToJson(metrics_tree);
  EXPECT_EQ(metrics["total"], 4);  // bonus 2 added in ticks 2 and 3
  EXPECT_EQ(metrics["cfg"], "c");
}

TEST(LoopEntities, LoopFunctionChildrenAreParams) {
  TempDir d;
  d.Write("c.lua", kStill);
  d.Write("loop.lua",
          "function post_experiment() return {r = experiment.params.params.reset_all, "
          "n = experiment.params.zone.radius, s = experiment.params.script} end");
  Scene s = Load(d, LoopExperiment(FootBot("fb0", 0, 0, 0, "c"), SensingController("c.lua"),
                                   "<params reset_all=\"true\"/><zone radius=\"0.5\"/>"));
  ASSERT_TRUE(s.ok()) << s.error;
  Value metrics_tree;
  bool has = false;
  std::string err;
  ASSERT_TRUE(FinishRun(*s.world, &metrics_tree, &has, &err)) << err;
  Json metrics = ToJson(metrics_tree);
  EXPECT_EQ(metrics["r"], "true");
  EXPECT_EQ(metrics["n"], "0.5");
  EXPECT_EQ(metrics["s"], "loop.lua");
}

TEST(LoopEntities, LegacyLedPositionLoadsWithOneWarning) {
  TempDir d;
  d.Write("c.lua", kStill);
  d.Write("loop.lua", "");
  const std::string leds =
      "<leds medium=\"leds\"><led position=\"0.1,0,0.3\" color=\"red\"/>"
      "<led position=\"0,0.1,0.3\" color=\"green\"/></leds>";
  std::string path = d.Write(
      "experiment.argos",
      LoopExperiment(Cylinder("a", 1, 0, false, leds) + Cylinder("b", 2, 0, false, leds), SensingController("c.lua")));
  ErrorList errors, warnings;
  auto model = LoadExperimentFile(path, {}, &errors, &warnings);
  ASSERT_TRUE(model) << errors.Format();
  ASSERT_EQ(model->obstacles[1].leds.size(), 2u);
  EXPECT_TRUE(model->obstacles[1].leds[1].offset.isApprox(Vec3(0, 0.1, 0.3)));
  EXPECT_EQ(model->obstacles[1].leds[1].color.g, 255);
  EXPECT_EQ(warnings.Size(), 1u) << warnings.Format();
  EXPECT_NE(warnings.Format().find("legacy <led position"), std::string::npos) << warnings.Format();
}

TEST(LoopEntities, BadCallsNameTheHookAndTheLine) {
  auto expect = [](const std::string& loop, const std::string& text, const std::string& arena = "") {
    std::string f = Fails(loop, arena);
    EXPECT_NE(f.find(text), std::string::npos) << loop << "\n=> " << f;
  };
  expect("function pre_step()\n  experiment.entities('tree')\nend", "loop functions (pre_step): ");
  expect("function pre_step()\n  experiment.entities('tree')\nend", "loop.lua:2: entities: unknown kind 'tree'");
  expect("function init()\n  experiment.add_entity('box', {position = {1, 1}})\nend",
         "loop.lua:2: add_entity: a box spec needs 'size'");
  expect("function init() experiment.add_entity('light', {position = {1, 1}, color = 'plaid', medium = 'leds'}) end",
         "add_entity: bad colour 'plaid'");
  expect("function init() experiment.add_entity('light', {position = {1, 1}, color = 'red', medium = 'nope'}) end",
         "medium 'nope' is not declared");
  expect(
      "function post_step()\n  local c = experiment.entities('cylinder')[1]\n  experiment.remove_entity(c)\n"
      "  c:position()\nend",
      "loop.lua:4: position: cylinder 'cyl' was removed", Cylinder("cyl", 1, 1, true));
  expect("function post_step() experiment.entities('cylinder')[1]:set_led_color('plaid') end",
         "set_led_color: bad colour 'plaid'",
         Cylinder("cyl", 1, 1, true, "<leds medium=\"leds\"><led offset=\"0,0,0.3\" color=\"red\"/></leds>"));
  expect("function post_step() experiment.entities('cylinder')[1]:set_pose(2, 2) end",
         "set_pose: cylinder 'cyl' is static", Cylinder("cyl", 1, 1, false));
  expect("function post_step() experiment.robots[1]:intensity() end", "intensity: 'fb0' is a foot-bot, not a light");
  expect("function post_step() experiment.remove_entity(experiment.robots[1]) end", "foot-bots cannot be removed");
  expect("function post_step() experiment.robots[1]:set_lua_global('x', print) end",
         "set_lua_global: 'x' must be plain data");
  expect("function init() experiment.add_entity('box', {id = 'fb0', position = {1, 1}, size = {1, 1, 1}}) end",
         "id 'fb0' is already used");
}

// The store keeps its ids in an index (HasId is a lookup): an id is taken from its
// entity's addition to its removal, whatever the kind, and free again after.
TEST(LoopEntities, AnIdIsTakenUntilItsEntityIsRemoved) {
  const std::string add_box = "experiment.add_entity('box', {id = 'b', position = {1, 1}, size = {0.1, 0.1, 0.1}})\n";
  EXPECT_EQ(Fails("function init()\n  local b = " + add_box + "  experiment.remove_entity(b)\n  " + add_box + "end"),
            "");
  EXPECT_NE(Fails("function init()\n  " + add_box + "  " + add_box + "end").find("id 'b' is already used"),
            std::string::npos);
  EXPECT_NE(Fails("function init()\n  experiment.add_entity('light', {id = 'cyl', position = {1, 1}, color = 'red', "
                  "medium = 'leds'})\nend",
                  Cylinder("cyl", 2, 2, true))
                .find("id 'cyl' is already used"),
            std::string::npos);
  EXPECT_EQ(Fails("function post_step()\n  local c = experiment.entities('cylinder')[1]\n  if c then\n"
                  "    experiment.remove_entity(c)\n    experiment.add_entity('light', {id = 'cyl', position = {1, 1}, "
                  "color = 'red', medium = 'leds'})\n  end\nend",
                  Cylinder("cyl", 2, 2, true)),
            "");
}

TEST(LoopEntities, AddingAndRemovingIsIdenticalAtAnyThreadCount) {
  TempDir d;
  d.Write("c.lua", R"(
function init() robot.colored_blob_omnidirectional_camera.enable() end
function step()
  local n = #robot.colored_blob_omnidirectional_camera
  robot.wheels.set_velocity(5 + n, 5 - n + robot.random.uniform(-2, 2))
end
)");
  d.Write("loop.lua", R"(
function post_step()
  local t = experiment.tick
  if t % 7 == 0 then
    experiment.add_entity("cylinder", {position = {experiment.random.uniform(-2, 2), experiment.random.uniform(-2, 2)},
      radius = 0.05, height = 0.2, movable = true, mass = 0.2, medium = "leds",
      leds = {{offset = {0, 0, 0.2}, color = "red"}}})
  end
  local cs = experiment.entities("cylinder")
  if t % 11 == 0 and #cs > 0 then experiment.remove_entity(cs[1]) end
  if #cs > 1 then cs[2]:set_led_color("blue") end
end
)");
  std::string arena;
  for (int i = 0; i < 12; ++i) arena += FootBot("fb" + std::to_string(i), -1.5 + 0.3 * i, (i % 3) * 0.4, 30.0 * i, "c");
  uint64_t hashes[2];
  int k = 0;
  for (int threads : {1, 4}) {
    Scene s = Load(
        d, LoopExperiment(arena,
                          "<lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/>"
                          "</actuators><sensors><colored_blob_omnidirectional_camera implementation=\"rot_z_only\" "
                          "medium=\"leds\"/></sensors><params script=\"c.lua\"/></lua_controller>",
                          "", threads));
    ASSERT_TRUE(s.ok()) << s.error;
    for (int i = 0; i < 80; ++i) ASSERT_EQ(Step(*s.world), StepStatus::Running) << s.world->failure;
    ASSERT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
    hashes[k++] = PoseHash(*s.world);
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

}  // namespace
}  // namespace essaim
