// Entity handles of the loop functions (internal to loop_functions.cpp and
// loop_entities.cpp): one full userdata per entity, {kind, serial}, its id as user value,
// cached so that every call hands out the same object (experiment.robots[i] ==
// experiment.entities("foot-bot")[i]).
#pragma once
#include "devices/entity_store.h"

struct lua_State;

namespace essaim {

struct EntityHandle {
  EntityRef ref;
};

/// Registry keys (by address).
extern const char kHandleMetaKey, kHandleCacheKey;

class LoopFunctions;
/// The loop functions that own `L` (kept in its extra space, see Load).
LoopFunctions* LoopFunctionsOf(lua_State* L);

/// Pushes the handle of `e`, creating it (with `id`) on first use.
void PushEntityHandle(lua_State* L, const EntityRef& e, const char* id);
/// The handle at `idx`, or nullptr when it is not one.
EntityHandle* ToEntityHandle(lua_State* L, int idx);
/// Fills the handle metatable (`index` is the robot-only __index fallback already set)
/// and adds entities / add_entity / remove_entity to the table at `experiment`.
void OpenEntityApi(lua_State* L, int experiment);

}  // namespace essaim
