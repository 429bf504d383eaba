// No heap churn in the step: after warm-up, a tick makes no C++ allocation (operator new is
// counted here), and the Lua states allocate only what the ARGoS contract requires.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "output/recording.h"
#include "support/scene.h"

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
// The nothrow forms too (std::stable_sort's temporary buffer): left to the runtime, they
// would allocate with its new and be freed here (ASan: alloc-dealloc-mismatch).
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  g_news.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

namespace essaim {
namespace {
using namespace essaim::testing;

// Every device that needs no medium, a loop function with a time series, 30 robots in a
// walled arena with obstacles: a busy step.
const char* kController = R"(
function init() robot.distance_scanner.enable() robot.distance_scanner.set_rpm(60) end
function step()
  local left, right = 10, 10
  for i = 1, 24 do
    if robot.proximity[i].value > 0.05 then
      if robot.proximity[i].angle > 0 then right = -5 else left = -5 end
    end
  end
  local g = robot.motor_ground[1].value + robot.base_ground[1].value + robot.light[1].value
  local p = robot.positioning.position
  robot.wheels.set_velocity(left, right)
end
)";

const char* kLoop = R"(
function floor_color(x, y) if x * x + y * y < 0.25 then return 0, 0, 0 end return 255, 255, 255 end
function post_step()
  if experiment.tick % 10 == 0 then
    local alive = 0
    for _, r in ipairs(experiment.robots) do if r:alive() then alive = alive + 1 end end
    experiment.timeseries({{"tick", experiment.tick}, {"alive", alive}})
  end
end
)";

std::string Busy() {
  std::string sensors =
      "<footbot_proximity implementation=\"default\"/><footbot_light implementation=\"rot_z_only\"/>"
      "<footbot_base_ground implementation=\"rot_z_only\"/><footbot_motor_ground implementation=\"rot_z_only\"/>"
      "<footbot_distance_scanner implementation=\"rot_z_only\"/><battery implementation=\"default\"/>";
  std::string ctrl =
      "<lua_controller id=\"c\"><actuators><differential_steering implementation=\"default\"/>"
      "<footbot_distance_scanner implementation=\"default\"/></actuators>"
      "<sensors><differential_steering implementation=\"default\"/><positioning implementation=\"default\"/>" +
      sensors + "</sensors><params script=\"c.lua\"/></lua_controller>";
  std::string arena =
      "<floor id=\"f\" source=\"loop_functions\" pixels_per_meter=\"20\"/>"
      "<light id=\"l\" position=\"2,2,0.5\" orientation=\"0,0,0\" color=\"yellow\" intensity=\"1\" medium=\"leds\"/>"
      "<box id=\"w1\" size=\"0.1,8,0.5\" movable=\"false\"><body position=\"4,0,0\"/></box>"
      "<box id=\"w2\" size=\"0.1,8,0.5\" movable=\"false\"><body position=\"-4,0,0\"/></box>"
      "<box id=\"w3\" size=\"8,0.1,0.5\" movable=\"false\"><body position=\"0,4,0\"/></box>"
      "<box id=\"w4\" size=\"8,0.1,0.5\" movable=\"false\"><body position=\"0,-4,0\"/></box>"
      "<distribute><position method=\"uniform\" min=\"-3.5,-3.5,0\" max=\"3.5,3.5,0\"/>"
      "<orientation method=\"constant\" values=\"0,0,0\"/><entity quantity=\"20\" max_trials=\"50\">"
      "<cylinder id=\"c\" radius=\"0.1\" height=\"0.5\" movable=\"false\"/></entity></distribute>"
      "<distribute><position method=\"uniform\" min=\"-3.5,-3.5,0\" max=\"3.5,3.5,0\"/>"
      "<orientation method=\"uniform\" min=\"0,0,0\" max=\"360,0,0\"/><entity quantity=\"30\" max_trials=\"50\">"
      "<foot-bot id=\"fb\"><controller config=\"c\"/><battery discharge_model=\"time\" delta=\"0.001\"/></foot-bot>"
      "</entity></distribute>";
  return Experiment(arena, ctrl, 10000, 3, "<loop_functions script=\"loop.lua\"/>");
}

TEST(Allocations, AStepMakesNoCppAllocationAfterWarmUp) {
  TempDir d;
  d.Write("c.lua", kController);
  d.Write("loop.lua", kLoop);
  for (int threads : {1, 2}) {
    LoadOptions lo;
    lo.threads = threads;
    Scene s = Load(d, Busy(), lo);
    ASSERT_TRUE(s.ok()) << s.error << s.errors.Format();
    RunTicks(*s.world, 50);  // warm-up: contacts, Lua tables, buffers reach their size
    long before = g_news.load();
    RunTicks(*s.world, 9);  // between two time-series rows (the series grows by design)
    EXPECT_EQ(g_news.load() - before, 0) << "threads=" << threads;
    EXPECT_TRUE(s.world->controller_errors.empty()) << s.world->controller_errors[0].message;
  }
}

// The recorder copies a frame into the buffer Open() made; it keeps slots aside (and
// allocates) only for robots and obstacles the loop functions add during the run.
TEST(Allocations, RecordingAFrameMakesNoCppAllocation) {
  TempDir d;
  d.Write("c.lua", kController);
  d.Write("loop.lua", kLoop);
  Scene s = Load(d, Busy());
  ASSERT_TRUE(s.ok()) << s.error << s.errors.Format();
  RecordingWriter rec;
  std::string error;
  ASSERT_TRUE(rec.Open(d.path() + "/recording.bin", *s.world, 1, &error)) << error;
  auto record = [&](int ticks) {
    for (int t = 0; t < ticks; ++t) {
      Step(*s.world);
      rec.Record(*s.world);
    }
  };
  record(50);
  long before = g_news.load();
  record(9);
  EXPECT_EQ(g_news.load() - before, 0);
  EXPECT_EQ(rec.FramesWritten(), 60u);
  EXPECT_TRUE(rec.Finish(*s.world, &error)) << error;
}

TEST(Allocations, LuaMemoryStaysFlat) {
  TempDir d;
  d.Write("c.lua", kController);
  d.Write("loop.lua", kLoop);
  Scene s = Load(d, Busy());
  ASSERT_TRUE(s.ok()) << s.error << s.errors.Format();
  auto bytes = [&] {
    size_t b = 0;
    for (const auto& c : s.world->controllers) b += c->Memory().bytes;
    return b;
  };
  auto allocations = [&] {
    size_t n = 0;
    for (const auto& c : s.world->controllers) n += c->Memory().allocations;
    return n;
  };
  RunTicks(*s.world, 100);
  size_t a0 = allocations();
  RunTicks(*s.world, 100);
  // The ARGoS contract hands out a fresh position and orientation value every step
  // (controllers keep last step's); those two small userdata are all the host allocates
  // per robot-step for this controller, and the collector returns them.
  double per_robot_step = static_cast<double>(allocations() - a0) / (100 * 30);
  EXPECT_LE(per_robot_step, 2.5);
  size_t after200 = bytes();
  RunTicks(*s.world, 1000);
  EXPECT_LT(static_cast<double>(bytes()), 1.5 * static_cast<double>(after200) + 30 * 4096)
      << "Lua memory grows: " << after200 << " -> " << bytes();
  EXPECT_LT(bytes() / 30, 60u * 1024) << "bytes per robot state";
}

}  // namespace
}  // namespace essaim
