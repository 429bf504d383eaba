// Entity handles of the loop functions (internal to lua/loop/): one full userdata per
// entity, {kind, serial}, its id as user value, cached so that every call hands out the
// same object (experiment.robots[i] == experiment.entities("foot-bot")[i]).
#pragma once
#include "devices/entity_store.h"

struct lua_State;

namespace essaim {

struct EntityHandle {
  EntityRef ref;
};

/// Registry keys (by address). kRobotListKey: experiment.robots, which add_entity extends.
extern const char kHandleMetaKey, kHandleCacheKey, kRobotListKey;

/// Pushes the handle of `e`, creating it (with `id`) on first use.
void PushEntityHandle(lua_State* L, const EntityRef& e, const char* id);
/// The handle at `idx`, or nullptr when it is not one.
EntityHandle* ToEntityHandle(lua_State* L, int idx);
/// Makes the handle metatable: robot methods (battery, kill, lua_global...) and, through
/// OpenEntityApi, the methods every entity has.
void OpenRobotApi(lua_State* L);
/// Fills the handle metatable with the methods every entity has (pose, LEDs, light) and
/// adds entities / add_entity / remove_entity to the table at `experiment`.
void OpenEntityApi(lua_State* L, int experiment);
/// experiment.add_entity(kind, spec) (loop_add_entity.cpp).
int AddEntity(lua_State* L);
/// experiment.timeseries({{name, value}, ...}).
int AppendTimeseriesRow(lua_State* L);

}  // namespace essaim
