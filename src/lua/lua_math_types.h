// vector2, vector3 and quaternion userdata with ARGoS's Lua semantics (spec §8.2).
#pragma once
#include <lua.hpp>

namespace essaim {

/// Registers the metatables and the global constructors vector2, vector3, quaternion.
void OpenMathTypes(lua_State* L);
void PushVector3(lua_State* L, double x, double y, double z);
void PushQuaternion(lua_State* L, double w, double x, double y, double z);
void PushVector2(lua_State* L, double x, double y);

}  // namespace essaim
