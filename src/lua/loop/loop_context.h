// What the loop functions' Lua bindings reach from a lua_State (LoopContextOf): the World's
// entities through their one public interface (EntityStore), the controllers' states (for
// r:lua_global), and the loop functions' own records and scratch. Owned by LoopFunctions.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "devices/entity_store.h"
#include "lua/loop/lua_copy.h"
#include "lua/robot/lua_controller.h"
#include "model/model.h"

struct lua_State;

namespace essaim {

struct Timeseries {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

struct LoopContext {
  const Model* model = nullptr;
  EntityStore* entities = nullptr;
  std::vector<std::unique_ptr<RobotController>>* controllers = nullptr;  // may be empty until init()
  std::string script;
  uint64_t tick = 0;
  const void* handle_meta = nullptr;  // the handle metatable, compared by address
  std::string log;
  Timeseries series;
  bool warned_nonfinite_row = false;  // timeseries(): NaN/inf is warned about once per run
  bool floor_changed = false;         // experiment.floor_changed() since the floor was last drawn
  // Scratch that Lua errors may unwind past without leaking: add_entity's spec, lua_global's
  // copy (C++ locals with destructors must not live across a Lua error).
  ObstacleDef obstacle_spec;
  LightDef light_spec;
  RobotDef robot_spec;
  std::string add_error;
  LuaTape tape;
};

/// The context of the loop functions that own `L` (kept in its extra space, see Load).
LoopContext* LoopContextOf(lua_State* L);

}  // namespace essaim
