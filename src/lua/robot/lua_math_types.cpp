#include "lua/robot/lua_math_types.h"

#include <cmath>
#include <cstring>
#include <string>

namespace essaim {

namespace {
constexpr const char* kV2 = "vector2";
constexpr const char* kV3 = "vector3";
constexpr const char* kQ = "quaternion";
constexpr double kPiLocal = 3.14159265358979323846;

struct V2 {
  double x, y;
};
struct V3 {
  double x, y, z;
};
struct Q {
  double w, x, y, z;
};

V2* CheckV2(lua_State* L, int i) { return static_cast<V2*>(luaL_checkudata(L, i, kV2)); }
V3* CheckV3(lua_State* L, int i) { return static_cast<V3*>(luaL_checkudata(L, i, kV3)); }
Q* CheckQ(lua_State* L, int i) { return static_cast<Q*>(luaL_checkudata(L, i, kQ)); }

// Metatables are also kept under light-userdata keys: fetching them by address avoids
// interning the type name for every value pushed (positioning pushes two per robot-step).
const char kV2Key = 0, kV3Key = 0, kQKey = 0;
void MakeMetaOf(lua_State* L, const char* key);
// A type's metatable is made with its first value (2 KB a state for the three, which many
// controllers never use): no value of the type exists before it, so luaL_checkudata and
// luaL_testudata answer the same either way.
template <class T>
T* NewUd(lua_State* L, const char* key) {
  auto* p = static_cast<T*>(lua_newuserdatauv(L, sizeof(T), 0));
  if (lua_rawgetp(L, LUA_REGISTRYINDEX, key) == LUA_TNIL) {
    lua_pop(L, 1);
    MakeMetaOf(L, key);
    lua_rawgetp(L, LUA_REGISTRYINDEX, key);
  }
  lua_setmetatable(L, -2);
  return p;
}
V2* NewV2(lua_State* L) { return NewUd<V2>(L, &kV2Key); }
V3* NewV3(lua_State* L) { return NewUd<V3>(L, &kV3Key); }
Q* NewQ(lua_State* L) { return NewUd<Q>(L, &kQKey); }

std::string FormatNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// ---------------------------------------------------------------- vector2
int V2New(lua_State* L) {
  int n = lua_gettop(L);
  V2 v{0, 0};
  if (n == 1)
    v = *CheckV2(L, 1);
  else if (n == 2)
    v = {luaL_checknumber(L, 1), luaL_checknumber(L, 2)};
  else if (n != 0)
    return luaL_error(L, "vector2 expects 0, 1 or 2 arguments");
  *NewV2(L) = v;
  return 1;
}
int V2Length(lua_State* L) {
  V2* v = CheckV2(L, 1);
  lua_pushnumber(L, std::hypot(v->x, v->y));
  return 1;
}
int V2Dot(lua_State* L) {
  V2* a = CheckV2(L, 1);
  V2* b = CheckV2(L, 2);
  lua_pushnumber(L, a->x * b->x + a->y * b->y);
  return 1;
}
int V2Normalize(lua_State* L) {
  V2* v = CheckV2(L, 1);
  double l = std::hypot(v->x, v->y);
  if (l > 0) v->x /= l, v->y /= l;
  lua_settop(L, 1);
  return 1;
}
int V2Rotate(lua_State* L) {
  V2* v = CheckV2(L, 1);
  double a = luaL_checknumber(L, 2), c = std::cos(a), s = std::sin(a);
  double x = v->x * c - v->y * s, y = v->x * s + v->y * c;
  v->x = x, v->y = y;
  lua_settop(L, 1);
  return 1;
}
// ARGoS quirk: vector2:cross computes a scalar, discards it and returns self.
int V2Cross(lua_State* L) {
  CheckV2(L, 1);
  CheckV2(L, 2);
  lua_settop(L, 1);
  return 1;
}
int V2Angle(lua_State* L) {
  V2* v = CheckV2(L, 1);
  lua_pushnumber(L, std::atan2(v->y, v->x));
  return 1;
}
int V2Index(lua_State* L) {
  V2* v = CheckV2(L, 1);
  const char* k = lua_tostring(L, 2);
  if (k && k[0] && !k[1]) {
    if (k[0] == 'x') return lua_pushnumber(L, v->x), 1;
    if (k[0] == 'y') return lua_pushnumber(L, v->y), 1;
  }
  luaL_getmetatable(L, kV2);
  lua_pushvalue(L, 2);
  lua_rawget(L, -2);
  return 1;
}
int V2NewIndex(lua_State* L) {
  V2* v = CheckV2(L, 1);
  const char* k = luaL_checkstring(L, 2);
  double x = luaL_checknumber(L, 3);
  if (!std::strcmp(k, "x"))
    v->x = x;
  else if (!std::strcmp(k, "y"))
    v->y = x;
  else
    return luaL_error(L, "vector2 has no field '%s'", k);
  return 0;
}
int V2Add(lua_State* L) {
  V2 a = *CheckV2(L, 1), b = *CheckV2(L, 2);
  *NewV2(L) = {a.x + b.x, a.y + b.y};
  return 1;
}
int V2Sub(lua_State* L) {
  V2 a = *CheckV2(L, 1), b = *CheckV2(L, 2);
  *NewV2(L) = {a.x - b.x, a.y - b.y};
  return 1;
}
int V2Unm(lua_State* L) {
  V2 a = *CheckV2(L, 1);
  *NewV2(L) = {-a.x, -a.y};
  return 1;
}
int V2Mul(lua_State* L) {
  int vi = lua_isnumber(L, 1) ? 2 : 1;
  V2 a = *CheckV2(L, vi);
  double s = luaL_checknumber(L, vi == 1 ? 2 : 1);
  *NewV2(L) = {a.x * s, a.y * s};
  return 1;
}
int V2Div(lua_State* L) {
  V2 a = *CheckV2(L, 1);
  double s = luaL_checknumber(L, 2);
  *NewV2(L) = {a.x / s, a.y / s};
  return 1;
}
int V2Eq(lua_State* L) {
  V2* a = CheckV2(L, 1);
  V2* b = CheckV2(L, 2);
  lua_pushboolean(L, a->x == b->x && a->y == b->y);
  return 1;
}
int V2ToString(lua_State* L) {
  V2* v = CheckV2(L, 1);
  lua_pushstring(L, (FormatNumber(v->x) + "," + FormatNumber(v->y)).c_str());
  return 1;
}

// ---------------------------------------------------------------- vector3
int V3New(lua_State* L) {
  int n = lua_gettop(L);
  V3 v{0, 0, 0};
  if (n == 1)
    v = *CheckV3(L, 1);
  else if (n == 3)
    v = {luaL_checknumber(L, 1), luaL_checknumber(L, 2), luaL_checknumber(L, 3)};
  else if (n != 0)
    return luaL_error(L, "vector3 expects 0, 1 or 3 arguments");
  *NewV3(L) = v;
  return 1;
}
int V3Length(lua_State* L) {
  V3* v = CheckV3(L, 1);
  lua_pushnumber(L, std::sqrt(v->x * v->x + v->y * v->y + v->z * v->z));
  return 1;
}
int V3Dot(lua_State* L) {
  V3* a = CheckV3(L, 1);
  V3* b = CheckV3(L, 2);
  lua_pushnumber(L, a->x * b->x + a->y * b->y + a->z * b->z);
  return 1;
}
int V3Normalize(lua_State* L) {
  V3* v = CheckV3(L, 1);
  double l = std::sqrt(v->x * v->x + v->y * v->y + v->z * v->z);
  if (l > 0) v->x /= l, v->y /= l, v->z /= l;
  lua_settop(L, 1);
  return 1;
}
void RotateByQ(V3* v, const Q& q) {
  // v' = q v q^-1 (q assumed unit, as ARGoS does not normalise here either)
  double ux = q.x, uy = q.y, uz = q.z, s = q.w;
  double dot_uv = ux * v->x + uy * v->y + uz * v->z;
  double dot_uu = ux * ux + uy * uy + uz * uz;
  double cx = uy * v->z - uz * v->y, cy = uz * v->x - ux * v->z, cz = ux * v->y - uy * v->x;
  double x = 2 * dot_uv * ux + (s * s - dot_uu) * v->x + 2 * s * cx;
  double y = 2 * dot_uv * uy + (s * s - dot_uu) * v->y + 2 * s * cy;
  double z = 2 * dot_uv * uz + (s * s - dot_uu) * v->z + 2 * s * cz;
  v->x = x, v->y = y, v->z = z;
}
int V3Rotate(lua_State* L) {
  V3* v = CheckV3(L, 1);
  RotateByQ(v, *CheckQ(L, 2));
  lua_settop(L, 1);
  return 1;
}
int V3Cross(lua_State* L) {
  V3* a = CheckV3(L, 1);
  V3 b = *CheckV3(L, 2);
  V3 r{a->y * b.z - a->z * b.y, a->z * b.x - a->x * b.z, a->x * b.y - a->y * b.x};
  *a = r;
  lua_settop(L, 1);
  return 1;
}
int V3Index(lua_State* L) {
  V3* v = CheckV3(L, 1);
  const char* k = lua_tostring(L, 2);
  if (k && k[0] && !k[1]) {
    if (k[0] == 'x') return lua_pushnumber(L, v->x), 1;
    if (k[0] == 'y') return lua_pushnumber(L, v->y), 1;
    if (k[0] == 'z') return lua_pushnumber(L, v->z), 1;
  }
  luaL_getmetatable(L, kV3);
  lua_pushvalue(L, 2);
  lua_rawget(L, -2);
  return 1;
}
int V3NewIndex(lua_State* L) {
  V3* v = CheckV3(L, 1);
  const char* k = luaL_checkstring(L, 2);
  double x = luaL_checknumber(L, 3);
  if (!std::strcmp(k, "x"))
    v->x = x;
  else if (!std::strcmp(k, "y"))
    v->y = x;
  else if (!std::strcmp(k, "z"))
    v->z = x;
  else
    return luaL_error(L, "vector3 has no field '%s'", k);
  return 0;
}
int V3Add(lua_State* L) {
  V3 a = *CheckV3(L, 1), b = *CheckV3(L, 2);
  *NewV3(L) = {a.x + b.x, a.y + b.y, a.z + b.z};
  return 1;
}
int V3Sub(lua_State* L) {
  V3 a = *CheckV3(L, 1), b = *CheckV3(L, 2);
  *NewV3(L) = {a.x - b.x, a.y - b.y, a.z - b.z};
  return 1;
}
int V3Unm(lua_State* L) {
  V3 a = *CheckV3(L, 1);
  *NewV3(L) = {-a.x, -a.y, -a.z};
  return 1;
}
int V3Mul(lua_State* L) {
  int vi = lua_isnumber(L, 1) ? 2 : 1;
  V3 a = *CheckV3(L, vi);
  double s = luaL_checknumber(L, vi == 1 ? 2 : 1);
  *NewV3(L) = {a.x * s, a.y * s, a.z * s};
  return 1;
}
int V3Div(lua_State* L) {
  V3 a = *CheckV3(L, 1);
  double s = luaL_checknumber(L, 2);
  *NewV3(L) = {a.x / s, a.y / s, a.z / s};
  return 1;
}
int V3Eq(lua_State* L) {
  V3* a = CheckV3(L, 1);
  V3* b = CheckV3(L, 2);
  lua_pushboolean(L, a->x == b->x && a->y == b->y && a->z == b->z);
  return 1;
}
int V3ToString(lua_State* L) {
  V3* v = CheckV3(L, 1);
  lua_pushstring(L, (FormatNumber(v->x) + "," + FormatNumber(v->y) + "," + FormatNumber(v->z)).c_str());
  return 1;
}

// ---------------------------------------------------------------- quaternion
Q FromAngleAxis(double angle, const V3& axis) {
  double s = std::sin(angle / 2);
  return {std::cos(angle / 2), axis.x * s, axis.y * s, axis.z * s};
}
int QNew(lua_State* L) {
  int n = lua_gettop(L);
  Q q{1, 0, 0, 0};
  if (n == 1)
    q = *CheckQ(L, 1);
  else if (n == 2)
    q = FromAngleAxis(luaL_checknumber(L, 1), *CheckV3(L, 2));
  else if (n == 4)
    q = {luaL_checknumber(L, 1), luaL_checknumber(L, 2), luaL_checknumber(L, 3), luaL_checknumber(L, 4)};
  else if (n != 0)
    return luaL_error(L, "quaternion expects 0, 1, 2 or 4 arguments");
  *NewQ(L) = q;
  return 1;
}
void ToAngleAxis(const Q& q, double* angle, V3* axis) {
  double w = std::fmax(-1.0, std::fmin(1.0, q.w));
  *angle = 2 * std::acos(w);
  double s = std::sqrt(1 - w * w);
  if (s < 1e-12)
    *axis = {0, 0, 1};
  else
    *axis = {q.x / s, q.y / s, q.z / s};
}
void ToEuler(const Q& q, double* z, double* y, double* x) {
  // ZYX (yaw, pitch, roll), as ARGoS's ToEulerAngles.
  double sqw = q.w * q.w, sqx = q.x * q.x, sqy = q.y * q.y, sqz = q.z * q.z;
  *z = std::atan2(2 * (q.x * q.y + q.w * q.z), sqx - sqy - sqz + sqw);
  double sp = -2 * (q.x * q.z - q.w * q.y);
  *y = std::asin(std::fmax(-1.0, std::fmin(1.0, sp)));
  *x = std::atan2(2 * (q.y * q.z + q.w * q.x), -sqx - sqy + sqz + sqw);
}
int QToAngleAxis(lua_State* L) {
  Q* q = CheckQ(L, 1);
  double a;
  V3 ax;
  ToAngleAxis(*q, &a, &ax);
  lua_pushnumber(L, a);
  *NewV3(L) = ax;
  return 2;
}
int QToEuler(lua_State* L) {
  Q* q = CheckQ(L, 1);
  double z, y, x;
  ToEuler(*q, &z, &y, &x);
  lua_pushnumber(L, z);
  lua_pushnumber(L, y);
  lua_pushnumber(L, x);
  return 3;
}
int QNormalize(lua_State* L) {
  Q* q = CheckQ(L, 1);
  double l = std::sqrt(q->w * q->w + q->x * q->x + q->y * q->y + q->z * q->z);
  if (l > 0) q->w /= l, q->x /= l, q->y /= l, q->z /= l;
  lua_settop(L, 1);
  return 1;
}
int QInverse(lua_State* L) {
  Q q = *CheckQ(L, 1);
  *NewQ(L) = {q.w, -q.x, -q.y, -q.z};
  return 1;
}
int QIndex(lua_State* L) {
  Q* q = CheckQ(L, 1);
  const char* k = lua_tostring(L, 2);
  if (k) {
    if (!std::strcmp(k, "w")) return lua_pushnumber(L, q->w), 1;
    if (!std::strcmp(k, "x")) return lua_pushnumber(L, q->x), 1;
    if (!std::strcmp(k, "y")) return lua_pushnumber(L, q->y), 1;
    if (!std::strcmp(k, "z")) return lua_pushnumber(L, q->z), 1;
    // Pre-2019 controllers read orientation.angle and orientation.axis as fields.
    if (!std::strcmp(k, "angle") || !std::strcmp(k, "axis")) {
      double a;
      V3 ax;
      ToAngleAxis(*q, &a, &ax);
      if (k[1] == 'n')
        lua_pushnumber(L, a);
      else
        *NewV3(L) = ax;
      return 1;
    }
  }
  luaL_getmetatable(L, kQ);
  lua_pushvalue(L, 2);
  lua_rawget(L, -2);
  return 1;
}
int QNewIndex(lua_State* L) {
  Q* q = CheckQ(L, 1);
  const char* k = luaL_checkstring(L, 2);
  double v = luaL_checknumber(L, 3);
  if (!std::strcmp(k, "w"))
    q->w = v;
  else if (!std::strcmp(k, "x"))
    q->x = v;
  else if (!std::strcmp(k, "y"))
    q->y = v;
  else if (!std::strcmp(k, "z"))
    q->z = v;
  else
    return luaL_error(L, "quaternion has no field '%s'", k);
  return 0;
}
int QMul(lua_State* L) {
  Q a = *CheckQ(L, 1), b = *CheckQ(L, 2);
  *NewQ(L) = {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
              a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
  return 1;
}
int QEq(lua_State* L) {
  Q* a = CheckQ(L, 1);
  Q* b = CheckQ(L, 2);
  lua_pushboolean(L, a->w == b->w && a->x == b->x && a->y == b->y && a->z == b->z);
  return 1;
}
int QToString(lua_State* L) {
  Q* q = CheckQ(L, 1);
  double z, y, x;
  ToEuler(*q, &z, &y, &x);
  const double d = 180.0 / kPiLocal;
  lua_pushstring(L, (FormatNumber(z * d) + "," + FormatNumber(y * d) + "," + FormatNumber(x * d)).c_str());
  return 1;
}

void MakeMeta(lua_State* L, const char* name, const char* key, const luaL_Reg* meta, const luaL_Reg* methods) {
  luaL_newmetatable(L, name);
  luaL_setfuncs(L, meta, 0);
  luaL_setfuncs(L, methods, 0);  // methods live in the metatable, found by __index
  lua_rawsetp(L, LUA_REGISTRYINDEX, key);
}
const luaL_Reg v2_meta[] = {{"__index", V2Index},       {"__newindex", V2NewIndex}, {"__add", V2Add}, {"__sub", V2Sub},
                            {"__unm", V2Unm},           {"__mul", V2Mul},           {"__div", V2Div}, {"__eq", V2Eq},
                            {"__tostring", V2ToString}, {nullptr, nullptr}};
const luaL_Reg v2_methods[] = {{"length", V2Length}, {"dot", V2Dot},     {"normalize", V2Normalize},
                               {"rotate", V2Rotate}, {"cross", V2Cross}, {"angle", V2Angle},
                               {nullptr, nullptr}};
const luaL_Reg v3_meta[] = {{"__index", V3Index},       {"__newindex", V3NewIndex}, {"__add", V3Add}, {"__sub", V3Sub},
                            {"__unm", V3Unm},           {"__mul", V3Mul},           {"__div", V3Div}, {"__eq", V3Eq},
                            {"__tostring", V3ToString}, {nullptr, nullptr}};
const luaL_Reg v3_methods[] = {{"length", V3Length}, {"dot", V3Dot},     {"normalize", V3Normalize},
                               {"rotate", V3Rotate}, {"cross", V3Cross}, {nullptr, nullptr}};
const luaL_Reg q_meta[] = {{"__index", QIndex}, {"__newindex", QNewIndex}, {"__mul", QMul},
                           {"__eq", QEq},       {"__tostring", QToString}, {nullptr, nullptr}};
const luaL_Reg q_methods[] = {{"normalize", QNormalize},
                              {"inverse", QInverse},
                              {"toangleaxis", QToAngleAxis},
                              {"toeulerangles", QToEuler},
                              {nullptr, nullptr}};

void MakeMetaOf(lua_State* L, const char* key) {
  if (key == &kV2Key)
    MakeMeta(L, kV2, key, v2_meta, v2_methods);
  else if (key == &kV3Key)
    MakeMeta(L, kV3, key, v3_meta, v3_methods);
  else
    MakeMeta(L, kQ, key, q_meta, q_methods);
}
}  // namespace

void OpenMathTypes(lua_State* L) {
  lua_register(L, "vector2", V2New);
  lua_register(L, "vector3", V3New);
  lua_register(L, "quaternion", QNew);
}

void PushVector3(lua_State* L, double x, double y, double z) { *NewV3(L) = {x, y, z}; }
void PushVector2(lua_State* L, double x, double y) { *NewV2(L) = {x, y}; }
void PushQuaternion(lua_State* L, double w, double x, double y, double z) { *NewQ(L) = {w, x, y, z}; }

int MathTypeFields(lua_State* L, int idx, const char** names, double* values) {
  static const char* const kXyz[] = {"x", "y", "z"};
  static const char* const kWxyz[] = {"w", "x", "y", "z"};
  int n = 0;
  const double* v = nullptr;
  if (auto* a = static_cast<V2*>(luaL_testudata(L, idx, kV2)))
    n = 2, v = &a->x;
  else if (auto* b = static_cast<V3*>(luaL_testudata(L, idx, kV3)))
    n = 3, v = &b->x;
  else if (auto* q = static_cast<Q*>(luaL_testudata(L, idx, kQ)))
    n = 4, v = &q->w;
  for (int i = 0; i < n; ++i) {
    names[i] = n == 4 ? kWxyz[i] : kXyz[i];
    values[i] = v[i];
  }
  return n;
}

}  // namespace essaim
