// robot.random bound to one Rng: the table is pushed on the stack.
#pragma once
#include <lua.hpp>

#include "core/rng.h"

namespace essaim {

void PushRandomTable(lua_State* L, Rng* rng);

}  // namespace essaim
