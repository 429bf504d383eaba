// Foot-bots that loop functions add during a run (docs/loop-functions.md, add_entity): each
// gets a controller that runs init() at once and steps from the next tick, senses and is
// sensed as the file's robots are, and runs identically at any thread count; bad specs and
// failing scripts are errors naming the line, and nothing half-added stays behind.
#include <gtest/gtest.h>

#include <lua.hpp>

#include "support/scene.h"

namespace essaim {
namespace {
using namespace essaim::testing;

std::string Controller(const std::string& id, const std::string& script) {
  return "<lua_controller id=\"" + id +
         "\"><actuators><differential_steering implementation=\"default\"/>"
         "<range_and_bearing implementation=\"default\"/></actuators><sensors>"
         "<footbot_proximity implementation=\"default\" show_rays=\"false\"/>"
         "<range_and_bearing implementation=\"medium\" medium=\"rab\"/></sensors><params script=\"" +
         script + "\" speed=\"4\"/></lua_controller>";
}

std::string AddExperiment(const std::string& arena, const std::string& controllers, int threads = 1) {
  std::string xml = Experiment(arena, controllers, 1000, 3, "<loop_functions script=\"loop.lua\"/>\n");
  xml.replace(xml.find("<media/>"), 8, "<media><range_and_bearing id=\"rab\"/></media>");
  xml.replace(xml.find("<experiment "), 12, "<system threads=\"" + std::to_string(threads) + "\"/><experiment ");
  return xml;
}

// Counts steps, says one byte, and keeps what it heard and its largest proximity reading.
constexpr char kListener[] = R"(
function init() steps = 0; speed = robot.params.speed end
function step()
  steps = steps + 1
  robot.range_and_bearing.set_data(1, 7)
  heard = #robot.range_and_bearing
  near = 0
  for i = 1, 24 do near = math.max(near, robot.proximity[i].value) end
end
)";

double Global(World& w, int robot, const char* name) {
  lua_State* L = LuaStateOf(w.controllers[robot].get());
  lua_getglobal(L, name);
  const double v = lua_tonumber(L, -1);
  lua_pop(L, 1);
  return v;
}

TEST(LoopAddRobots, AnAddedRobotRunsSensesAndIsSensed) {
  TempDir d;
  d.Write("c.lua", kListener);
  d.Write("loop.lua", R"(
function init()
  local r = experiment.add_entity("foot-bot", {id = "fb1", controller = "c", position = {0.25, 0}, orientation = 180})
  assert(r == experiment.robots[2] and r == experiment.entities("foot-bot")[2] and r.kind == "foot-bot")
  assert(r:lua_global("speed") == "4", "init() ran during add_entity")
end
function post_step()
  if experiment.tick == 2 then
    local r = experiment.add_entity("foot-bot", {controller = "c", position = {-1, 0}})
    assert(r.id == "fb_2" and #experiment.robots == 3, r.id)
  end
end
)");
  Scene s = Load(d, AddExperiment(FootBot("fb0", 0, 0, 0, "c"), Controller("c", "c.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  ASSERT_TRUE(s.world->failure.empty()) << s.world->failure;
  for (int i = 0; i < 3; ++i) ASSERT_EQ(Step(*s.world), StepStatus::Running) << s.world->failure;
  World& w = *s.world;
  ASSERT_EQ(w.robots.size(), 3u);
  EXPECT_EQ(w.model.robots[1].id, "fb1");
  EXPECT_EQ(Global(w, 1, "steps"), 3);  // added in init(): stepped from the first tick
  EXPECT_EQ(Global(w, 2, "steps"), 1);  // added in post_step of tick 2: from tick 3
  EXPECT_EQ(Global(w, 0, "heard"), 2);
  EXPECT_EQ(Global(w, 1, "heard"), 1);  // fb0 hides the third from it
  EXPECT_GT(Global(w, 0, "near"), 0);   // 8 cm apart, face to face
  EXPECT_GT(Global(w, 1, "near"), 0);
  EXPECT_EQ(Global(w, 2, "near"), 0);
  EXPECT_EQ(w.robot_steps, 2u + 2 + 3);  // robots stepped at ticks 1, 2 and 3
  EXPECT_TRUE(w.controller_errors.empty());
}

TEST(LoopAddRobots, AddingRobotsIsIdenticalAtAnyThreadCount) {
  TempDir d;
  d.Write("c.lua", R"(
function step()
  local n = #robot.range_and_bearing
  robot.wheels.set_velocity(5 + n, 5 - n + robot.random.uniform(-2, 2))
end
)");
  // Some land on others: ARGoS adds where it is told, and the physics pushes them apart.
  d.Write("loop.lua", R"(
function post_step()
  if experiment.tick % 5 == 0 then
    experiment.add_entity("foot-bot", {controller = "c",
      position = {experiment.random.uniform(-1.5, 1.5), experiment.random.uniform(-1.5, 1.5)},
      orientation = experiment.random.uniform(0, 360)})
  end
end
)");
  std::string arena;
  for (int i = 0; i < 12; ++i) arena += FootBot("fb" + std::to_string(i), -1.5 + 0.3 * i, (i % 3) * 0.4, 30.0 * i, "c");
  uint64_t hashes[2];
  int k = 0;
  for (int threads : {1, 4}) {
    Scene s = Load(d, AddExperiment(arena, Controller("c", "c.lua"), threads));
    ASSERT_TRUE(s.ok()) << s.error;
    for (int i = 0; i < 60; ++i) ASSERT_EQ(Step(*s.world), StepStatus::Running) << s.world->failure;
    ASSERT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
    EXPECT_EQ(s.world->robots.size(), 24u);
    hashes[k++] = PoseHash(*s.world);
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

// The loop functions' failure (or the load error) when `loop` runs 2 ticks; "" if none.
std::string Fails(const std::string& loop, bool strict = false) {
  TempDir d;
  d.Write("c.lua", kListener);
  d.Write("bad.lua", "function init( end\n");
  d.Write("nostep.lua", "function init() end\n");
  d.Write("boom.lua", "function init() error('no battery') end\nfunction step() end\n");
  d.Write("loop.lua", loop);
  SimOptions options;
  options.strict = strict;
  const std::string controllers = Controller("c", "c.lua") + Controller("bad", "bad.lua") +
                                  Controller("nostep", "nostep.lua") + Controller("boom", "boom.lua");
  Scene s = Load(d, AddExperiment(FootBot("fb0", 0, 0, 0, "c"), controllers), {}, options);
  if (!s.ok()) return s.error;
  if (!s.world->failure.empty()) return s.world->failure;
  for (int i = 0; i < 2; ++i)
    if (Step(*s.world) == StepStatus::Failed) return s.world->failure;
  EXPECT_EQ(s.world->robots.size(), s.world->model.robots.size());
  EXPECT_EQ(s.world->robots.size(), s.world->controllers.size());
  return "";
}

std::string AddIn(const std::string& hook, const std::string& spec) {
  return "function " + hook + "()\n  experiment.add_entity('foot-bot', " + spec + ")\nend\n";
}

TEST(LoopAddRobots, BadSpecsAndFailingScriptsAreErrorsNamingTheLine) {
  auto expect = [](const std::string& loop, const std::string& text, bool strict = false) {
    std::string f = Fails(loop, strict);
    EXPECT_NE(f.find(text), std::string::npos) << loop << "\n=> " << f;
  };
  expect(AddIn("init", "{position = {1, 1}}"), "loop.lua:2: add_entity: spec needs 'controller'");
  expect(AddIn("init", "{controller = 'nope', position = {1, 1}}"), "add_entity: no controller with id 'nope'");
  expect(AddIn("post_step", "{id = 'fb0', controller = 'c', position = {1, 1}}"), "id 'fb0' is already used");
  expect(AddIn("init", "{controller = 'c', position = {9, 1}}"), "position (9, 1) is outside the arena");
  expect(AddIn("init", "{controller = 'c', position = {1, 1}, rab_data_size = 1.5}"), "'rab_data_size' must be");
  expect(AddIn("init", "{controller = 'c', position = {1, 1}, rab_range = -1}"), "'rab_range' must be >= 0");
  expect(AddIn("init", "{controller = 'bad', position = {1, 1}}"), "add_entity: robot fb_1: ");
  expect(AddIn("init", "{controller = 'bad', position = {1, 1}}"), "bad.lua:1:");
  expect(AddIn("init", "{controller = 'nostep', position = {1, 1}}"),
         "nostep.lua: no global function 'step' after init()");
  expect("experiment.add_entity('foot-bot', {controller = 'c', position = {1, 1}})",
         "foot-bots can be added from the loop functions' init() on");
  expect(AddIn("post_step", "{controller = 'boom', position = {1, 1}}"), "no battery", true);  // --strict
}

TEST(LoopAddRobots, AnInitErrorStopsThatRobotAloneAsAtTheStart) {
  TempDir d;
  d.Write("c.lua", kListener);
  d.Write("boom.lua", "function init() error('no battery') end\nfunction step() end\n");
  d.Write("loop.lua", AddIn("post_step", "{id = 'fb' .. experiment.tick, controller = 'boom', position = {1, 1}}"));
  Scene s =
      Load(d, AddExperiment(FootBot("fb0", 0, 0, 0, "c"), Controller("c", "c.lua") + Controller("boom", "boom.lua")));
  ASSERT_TRUE(s.ok()) << s.error;
  ASSERT_EQ(Step(*s.world), StepStatus::Running) << s.world->failure;
  ASSERT_EQ(s.world->robots.size(), 2u);
  EXPECT_FALSE(s.world->robots[1].controller_ok);
  ASSERT_EQ(s.world->controller_errors.size(), 1u);
  EXPECT_EQ(s.world->controller_errors[0].robot, "fb1");
  EXPECT_NE(s.world->controller_errors[0].message.find("boom.lua:1: no battery"), std::string::npos);
  EXPECT_EQ(Global(*s.world, 0, "steps"), 1);
}

}  // namespace
}  // namespace essaim
