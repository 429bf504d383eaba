// vector2, vector3 and quaternion userdata with ARGoS's Lua semantics.
#pragma once
#include <lua.hpp>

namespace essaim {

/// Registers the metatables and the global constructors vector2, vector3, quaternion.
void OpenMathTypes(lua_State* L);
void PushVector3(lua_State* L, double x, double y, double z);
void PushQuaternion(lua_State* L, double w, double x, double y, double z);
void PushVector2(lua_State* L, double x, double y);
/// The components of the vector2, vector3 or quaternion at `idx` (names "x", "y"[, "z"] or
/// "w", "x", "y", "z" into `names`, at most 4); 0 when it is none of these. Reads only.
int MathTypeFields(lua_State* L, int idx, const char** names, double* values);

}  // namespace essaim
