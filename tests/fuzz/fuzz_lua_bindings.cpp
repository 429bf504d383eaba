// The robot.* bindings' argument handling: each input is a sequence of calls of actuator
// functions with fuzzed arguments (numbers including NaN, ±inf and huge values, strings,
// tables, nil), made from a robot's own lua_State as a controller would, each followed by
// a tick of the world. Errors are fine; a crash, a sanitizer report or a non-finite pose
// is not.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <lua.hpp>
#include <memory>
#include <string>

#include "core/error_list.h"
#include "model/xml_loader.h"
#include "sim/step.h"
#include "sim/world.h"

using namespace essaim;

namespace {
const char* kXml = R"(<argos-configuration>
  <framework><experiment length="0" ticks_per_second="10" random_seed="1"/></framework>
  <controllers><lua_controller id="c">
    <actuators><differential_steering implementation="default"/><leds implementation="default" medium="leds"/>
      <range_and_bearing implementation="default"/><footbot_distance_scanner implementation="default"/>
      <footbot_gripper implementation="default"/><footbot_turret implementation="default"/></actuators>
    <sensors><differential_steering implementation="default"/><positioning implementation="default"/>
      <footbot_proximity implementation="default"/><footbot_distance_scanner implementation="rot_z_only"/>
      <range_and_bearing implementation="medium" medium="rab"/><footbot_turret_encoder implementation="default"/>
      <colored_blob_omnidirectional_camera implementation="rot_z_only" medium="leds"/></sensors>
    <params script="idle.lua"/></lua_controller></controllers>
  <arena size="4,4,1" center="0,0,0.5">
    <box id="w" size="0.1,4,0.5" movable="false"><body position="1.5,0,0" orientation="0,0,0"/></box>
    <cylinder id="o" radius="0.1" height="0.2" movable="true" mass="0.1"><body position="0.4,0,0" orientation="0,0,0"/></cylinder>
    <foot-bot id="a"><body position="0,0,0" orientation="0,0,0"/><controller config="c"/></foot-bot>
    <foot-bot id="b"><body position="-0.6,0.3,0" orientation="90,0,0"/><controller config="c"/></foot-bot>
  </arena>
  <physics_engines><dynamics2d id="dyn2d" iterations="10"/></physics_engines>
  <media><range_and_bearing id="rab"/><led id="leds"/></media>
</argos-configuration>)";

const char* kFunctions[][2] = {
    {"wheels", "set_velocity"},
    {"leds", "set_all_colors"},
    {"leds", "set_single_color"},
    {"range_and_bearing", "set_data"},
    {"range_and_bearing", "clear_data"},
    {"distance_scanner", "enable"},
    {"distance_scanner", "disable"},
    {"distance_scanner", "set_angle"},
    {"distance_scanner", "set_rpm"},
    {"gripper", "lock_positive"},
    {"gripper", "unlock"},
    {"turret", "set_rotation"},
    {"turret", "set_rotation_speed"},
    {"turret", "set_position_control_mode"},
    {"turret", "set_speed_control_mode"},
    {"turret", "set_passive_mode"},
    {"colored_blob_omnidirectional_camera", "enable"},
};
constexpr int kFunctionCount = sizeof kFunctions / sizeof kFunctions[0];

struct Bytes {
  const uint8_t* p;
  size_t n;
  uint8_t U8() {
    if (!n) return 0;
    --n;
    return *p++;
  }
  double F64() {
    uint8_t b[8] = {};
    for (uint8_t& x : b) x = U8();
    double d;
    std::memcpy(&d, b, 8);
    return d;
  }
};

void PushArgument(lua_State* L, Bytes& in) {
  static const double kSpecial[] = {NAN, INFINITY, -INFINITY, 1e300, -1e300, 0, 1, 13, 14, 256, -1, 1e18};
  switch (in.U8() % 7) {
    case 0:
      lua_pushnil(L);
      break;
    case 1:
      lua_pushinteger(L, static_cast<int8_t>(in.U8()));
      break;
    case 2:
      lua_pushnumber(L, kSpecial[in.U8() % (sizeof kSpecial / sizeof kSpecial[0])]);
      break;
    case 3:
      lua_pushnumber(L, in.F64());
      break;
    case 4: {
      static const char* kText[] = {"red", "255,0,0,255", "nope", "", "1,2", "0,0,0,0,0"};
      lua_pushstring(L, kText[in.U8() % 6]);
      break;
    }
    case 5: {  // an array of fuzzed numbers
      int len = in.U8() % 12;
      lua_createtable(L, len, 0);
      for (int i = 1; i <= len; ++i) {
        if (in.U8() % 4 == 0)
          lua_pushstring(L, "x");
        else
          lua_pushnumber(L, in.U8() % 3 == 0 ? in.F64() : in.U8());
        lua_rawseti(L, -2, i);
      }
      break;
    }
    default:
      lua_pushboolean(L, in.U8() & 1);
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static std::unique_ptr<Model> model = [] {
    ErrorList errors;
    LoadOptions options;
    options.working_dir = ESSAIM_FUZZ_DATA;  // idle.lua
    auto m = LoadExperimentText(kXml, "/nonexistent/fuzz.argos", options, &errors);
    if (!m) {
      std::fputs(errors.Format().c_str(), stderr);
      std::abort();
    }
    return m;
  }();
  SimOptions sim;
  sim.threads = 1;
  std::string error;
  std::unique_ptr<World> world = World::Create(*model, sim, &error);
  if (!world) std::abort();
  Bytes in{data, size};
  for (int call = 0; call < 16 && in.n > 0; ++call) {
    lua_State* L = LuaStateOf(world->controllers[in.U8() & 1].get());
    const char** fn = kFunctions[in.U8() % kFunctionCount];
    lua_getglobal(L, "robot");
    lua_getfield(L, -1, fn[0]);
    lua_getfield(L, -1, fn[1]);
    int nargs = in.U8() % 5;
    for (int a = 0; a < nargs; ++a) PushArgument(L, in);
    if (lua_isfunction(L, -1 - nargs)) lua_pcall(L, nargs, 0, 0);
    lua_settop(L, 0);
    Step(*world);
    for (int r = 0; r < world->physics.RobotCount(); ++r) {
      Pose2 p = world->physics.RobotPose(r);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.yaw)) __builtin_trap();
    }
  }
  return 0;
}
