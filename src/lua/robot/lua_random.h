// robot.random: the table is pushed on the stack.
#pragma once
#include <lua.hpp>

#include "core/rng.h"

namespace essaim {

/// Bound to `rng` (a closure per function): the loop functions' stream.
void PushRandomTable(lua_State* L, Rng* rng);
/// A controller's: light C functions drawing from RobotOf(L)'s controller_rng.
void PushRobotRandomTable(lua_State* L);

}  // namespace essaim
