// The guarded states' allocator: the memory cap and its accounting over the small-block pool.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <lua.hpp>

#include "lua/host/guard_hook.h"

namespace essaim {

namespace {
// The Lua line that asked for memory over the limit, in the running coroutine.
void RecordMemoryWhere(LuaGuard* g) {
  lua_State* L = g->running ? g->running : g->state;
  if (L) ScriptLine(L, g->memory_where, sizeof g->memory_where);
}

// Everything but the two common cases below: large blocks, reallocations, an empty free
// list, the memory limit. Out of line, so that the fast path saves no registers.
[[gnu::noinline]] void* SlowAlloc(LuaGuard* g, void* ptr, size_t old, size_t nsize) {
  if (nsize == 0) {
    std::free(ptr);  // a large block
    g->bytes -= old;
    return nullptr;
  }
  if (g->limit && nsize > old && g->bytes - old + nsize > g->limit) {
    if (!g->memory_exceeded) RecordMemoryWhere(g);
    g->memory_exceeded = true;
    return nullptr;  // Lua raises "not enough memory"; the owner reports the limit
  }
  void* p = nullptr;
  if (SmallBlockPool::IsSmall(old) && SmallBlockPool::IsSmall(nsize) && SmallBlockPool::SameClass(old, nsize)) {
    p = ptr;  // fits where it is
  } else if (!SmallBlockPool::IsSmall(old) && !SmallBlockPool::IsSmall(nsize)) {
    p = std::realloc(ptr, nsize);  // large to large (or new large): malloc's realloc
  } else {
    // Moving between the pool and malloc, or between classes.
    p = SmallBlockPool::IsSmall(nsize) ? g->pool.Allocate(nsize) : std::malloc(nsize);
    if (p && ptr) {
      std::memcpy(p, ptr, std::min(old, nsize));
      if (SmallBlockPool::IsSmall(old))
        g->pool.Free(ptr, old);
      else
        std::free(ptr);
    }
  }
  if (p) {
    g->bytes = g->bytes - old + nsize;
    g->peak = std::max(g->peak, g->bytes);
    ++g->allocations;
  }
  return p;
}
}  // namespace

bool ScriptLine(lua_State* L, char* out, size_t size) {
  lua_Debug ar;
  for (int level = 0; level < 8 && lua_getstack(L, level, &ar); ++level) {
    if (lua_getinfo(L, "Sl", &ar) && ar.currentline > 0) {
      std::snprintf(out, size, "%s:%d", ar.short_src, ar.currentline);
      return true;
    }
  }
  return false;
}

// Lua's objects are mostly small and short-lived: most calls free a small block or take a
// new one, which the pool's free lists serve without a call. The accounting (bytes, peak,
// allocations) is the same on every path.
void* GuardedAlloc(void* ud, void* ptr, size_t osize, size_t nsize) {
  auto* g = static_cast<LuaGuard*>(ud);
  const size_t old = ptr ? osize : 0;  // with no block, Lua passes the object's type
  if (nsize == 0) {
    if (!ptr) return nullptr;  // Lua "frees" the null array of every table without one
    if (!SmallBlockPool::IsSmall(old)) return SlowAlloc(g, ptr, old, nsize);
    g->pool.Free(ptr, old);
    g->bytes -= old;
    return nullptr;
  }
  if (!ptr && SmallBlockPool::IsSmall(nsize) && !(g->limit && g->bytes + nsize > g->limit)) {
    if (void* p = g->pool.TakeFree(nsize)) {
      g->bytes += nsize;
      g->peak = std::max(g->peak, g->bytes);
      ++g->allocations;
      return p;
    }
  }
  return SlowAlloc(g, ptr, old, nsize);
}

}  // namespace essaim
