// ARGoS's CLuaController (argos3/core/wrappers/lua/lua_controller.h): a robot's Lua
// controller, whose state loop functions read with the Lua C API. essaim runs Lua 5.4:
// code that calls Lua must be compiled with Lua 5.4's headers (docs/loop-functions.md).
#pragma once
extern "C" {
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
}

#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/core/utility/datatypes/datatypes.h>
#include <argos3/core/utility/math/rng.h>

static_assert(LUA_VERSION_NUM == 504,
              "essaim's controllers run Lua 5.4: compile loop functions that read a controller's state with "
              "Lua 5.4's headers (-DLUA_INCLUDE_DIR=/usr/include/lua5.4; docs/loop-functions.md)");

namespace argos {

class CLuaController : public CCI_Controller {
 public:
  /// GetId() gives `str_id`, the <lua_controller id> the robot runs.
  CLuaController(const std::string& str_id, UInt32 un_robot) : m_unRobot(un_robot) { SetId(str_id); }
  /// The robot's Lua state (its globals, the `robot` table), kept after a Lua error.
  lua_State* GetLuaState();
  /// Whether the controller runs (ARGoS: false after a Lua error).
  bool IsOK();

 private:
  UInt32 m_unRobot;
};

}  // namespace argos
