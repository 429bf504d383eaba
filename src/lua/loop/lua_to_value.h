// A loop function's Lua value (post_experiment()'s table) as a plain value tree, which
// output/ writes as metrics.json. Runs outside any protected call: it never raises.
#pragma once
#include <string>
#include <vector>

#include "core/value.h"

struct lua_State;

namespace essaim {

/// The value at `idx`: a table with keys 1..n only is a list (empty: []); other tables are
/// maps with keys sorted, so metrics.json does not depend on hashing. A metatable field
/// __jsontype = "array" | "object" settles empty or ambiguous tables. JSON has no NaN or
/// infinity: those become null and their key path goes to `nonfinite`. False with `error`
/// for functions, userdata, keys that are neither strings nor integers, or nesting deeper
/// than 32 tables.
bool LuaToValue(lua_State* L, int idx, Value* out, std::vector<std::string>* nonfinite, std::string* error);

}  // namespace essaim
