// experiment.timeseries({{name, value}, ...}): one row of timeseries.csv per call, the
// first row naming the columns.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <lua.hpp>

#include "lua/loop/loop_context.h"
#include "lua/loop/loop_handles.h"

namespace essaim {

namespace {
// Checks every item; leaves each one's name and value on the stack. Raises on a bad row.
void CheckRow(lua_State* L, const Timeseries& series, lua_Integer n, bool first) {
  const std::vector<std::string>& columns = series.columns;
  if (!first && static_cast<size_t>(n) != columns.size())
    luaL_error(L, "timeseries: row has %d columns, the first row had %d", (int)n, (int)columns.size());
  if (n < 0 || n > 100000) luaL_error(L, "timeseries: a row has 0 to 100000 columns, got %d", (int)n);
  luaL_checkstack(L, static_cast<int>(2 * n) + 3, "timeseries: too many columns");
  for (lua_Integer k = 1; k <= n; ++k) {
    lua_rawgeti(L, 1, k);
    if (!lua_istable(L, -1)) luaL_error(L, "timeseries: each item must be {name, value}");
    lua_rawgeti(L, -1, 1);
    lua_rawgeti(L, -2, 2);
    size_t len = 0;
    const char* name = lua_isstring(L, -2) ? lua_tolstring(L, -2, &len) : nullptr;  // a number becomes text here
    if (!name || !lua_isnumber(L, -1)) luaL_error(L, "timeseries: item %d must be {name, number}", (int)k);
    if (!first && (columns[k - 1].size() != len || std::memcmp(columns[k - 1].data(), name, len) != 0))
      luaL_error(L, "timeseries: column %d is '%s', expected '%s'", (int)k, name, columns[k - 1].c_str());
    lua_remove(L, -3);  // the item; its name and value stay
  }
}

void WarnNonFinite(LoopContext* ctx, size_t column_index) {
  if (ctx->warned_nonfinite_row) return;
  ctx->warned_nonfinite_row = true;
  std::string column = ctx->series.columns[column_index];
  std::replace(column.begin(), column.end(), '\n', ' ');  // one log line
  ctx->log += "Eloop functions: warning: timeseries(): NaN or infinite value in column '" + column + "' at tick " +
              std::to_string(ctx->tick) + ", written as NaN, Inf or -Inf in timeseries.csv (warned once per run)\n";
}
}  // namespace

// Two passes, so no Lua error unwinds through a C++ object (Debian's Lua longjmps, and a
// half-appended row would be left behind): the first checks every item and leaves its
// name and value on the stack; the second calls nothing that can raise and copies them.
int AppendTimeseriesRow(lua_State* L) {
  LoopContext* ctx = LoopContextOf(L);
  luaL_checktype(L, 1, LUA_TTABLE);
  const lua_Integer n = luaL_len(L, 1);
  const bool first = ctx->series.columns.empty() && ctx->series.rows.empty();
  CheckRow(L, ctx->series, n, first);
  const int base = lua_gettop(L) - static_cast<int>(2 * n);
  std::vector<double>& row = ctx->series.rows.emplace_back();
  row.reserve(static_cast<size_t>(n));
  int nonfinite = -1;
  for (int k = 0; k < n; ++k) {
    size_t len = 0;
    const char* name = lua_tolstring(L, base + 1 + 2 * k, &len);
    if (first) ctx->series.columns.emplace_back(name, len);  // whole, NUL bytes included
    row.push_back(lua_tonumber(L, base + 2 + 2 * k));
    if (nonfinite < 0 && !std::isfinite(row.back())) nonfinite = k;
  }
  if (nonfinite >= 0) WarnNonFinite(ctx, static_cast<size_t>(nonfinite));
  return 0;
}

}  // namespace essaim
