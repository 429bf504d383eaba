#include "lua/host/compiled_scripts.h"

#include <exception>
#include <lua.hpp>

namespace essaim {

namespace {
// lua_dump's writer: no C++ exception may cross Lua's C frames; a failure only means the
// chunk is not kept (the next state parses the file itself).
int AppendBytes(lua_State*, const void* bytes, size_t size, void* out) {
  try {
    static_cast<std::string*>(out)->append(static_cast<const char*>(bytes), size);
  } catch (const std::exception&) {
    return 1;
  }
  return 0;
}
}  // namespace

int CompiledScripts::Load(lua_State* L, const std::string& path, bool text_only) {
  const std::string key = (text_only ? "t:" : "bt:") + path;
  std::unique_lock<std::mutex> lock(mutex_);
  auto found = chunks_.find(key);
  if (found != chunks_.end()) {
    const Chunk& chunk = found->second;
    lock.unlock();
    if (chunk.status != LUA_OK) {
      lua_pushlstring(L, chunk.bytes.data(), chunk.bytes.size());
      return chunk.status;
    }
    // Our own dump: binary mode for this buffer only; "@path" as luaL_loadfile names it.
    const std::string chunkname = "@" + path;
    return luaL_loadbufferx(L, chunk.bytes.data(), chunk.bytes.size(), chunkname.c_str(), "b");
  }
  const int status = luaL_loadfilex(L, path.c_str(), text_only ? "t" : nullptr);
  Chunk chunk{status, {}};
  if (status != LUA_OK) {
    size_t len = 0;
    const char* message = lua_tolstring(L, -1, &len);
    if (!message) return status;  // not a string (out of memory): not kept
    chunk.bytes.assign(message, len);
  } else if (lua_dump(L, AppendBytes, &chunk.bytes, /*strip=*/0) != 0) {
    return status;  // not kept: the next state parses the file itself
  }
  chunks_.emplace(key, std::move(chunk));
  return status;
}

int CompiledScripts::LoadText(lua_State* L, const char* chunkname, const char* text, size_t size) {
  // Called inside Lua calls, where an error unwinds with longjmp: every Lua call here is
  // protected, and no C++ object is alive across one that could raise.
  const std::string* bytecode = nullptr;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto found = texts_.find(chunkname);
    if (found != texts_.end()) bytecode = &found->second;
  }
  if (bytecode) return luaL_loadbufferx(L, bytecode->data(), bytecode->size(), chunkname, "b");
  const int status = luaL_loadbufferx(L, text, size, chunkname, "t");
  if (status != LUA_OK) return status;
  std::string dumped;
  if (lua_dump(L, AppendBytes, &dumped, /*strip=*/0) == 0) {
    std::lock_guard<std::mutex> lock(mutex_);
    texts_.emplace(chunkname, std::move(dumped));
  }
  return status;
}

size_t CompiledScripts::Parsed() const {
  std::lock_guard<std::mutex> lock(mutex_);
  size_t parsed = 0;
  for (const auto& entry : chunks_) parsed += entry.second.status == LUA_OK;
  return parsed;
}

}  // namespace essaim
