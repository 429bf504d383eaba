// robot.params and experiment.params as tables that remember which keys the script read,
// so that a parameter given in the XML or by --set and never read can be reported (a typo
// such as EPSILONGRED would otherwise run silently with the default).
#pragma once
#include <string>
#include <vector>

struct lua_State;

namespace essaim {

/// Registry references to a tracked table's values and the keys read through it.
struct TrackedParams {
  int values_ref = -2;  // LUA_NOREF
  int read_ref = -2;
};

/// Pops a table of values and pushes in its place an empty proxy that reads and writes
/// through to it: indexing, assignment, pairs() and # behave as on the table itself, and
/// each string key looked up (present or not) or visited by pairs() is remembered.
/// next() and rawget() on the proxy see nothing (docs/compatibility.md).
void PushTrackedParams(lua_State* L, TrackedParams* refs);

/// The string keys holding string values (attributes, not child tables) that were never
/// read, and every key that was read; both sorted.
void ListParamReads(lua_State* L, const TrackedParams& refs, std::vector<std::string>* unread,
                    std::vector<std::string>* read);

}  // namespace essaim
