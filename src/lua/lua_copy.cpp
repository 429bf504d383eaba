#include "lua/lua_copy.h"

#include <lua.hpp>

namespace essaim {

void LuaTape::Clear() {
  items_.clear();
  strings_.clear();
  seen_.clear();
  tables_ = 0;
  bad_type_ = nullptr;
}

bool LuaTape::Record(lua_State* L, int idx, bool plain_only, const char** bad_type) {
  Clear();
  plain_only_ = plain_only;
  bool ok = RecordAt(L, lua_absindex(L, idx), 0);
  if (bad_type) *bad_type = bad_type_;
  return ok;
}

bool LuaTape::RecordAt(lua_State* L, int idx, int depth) {
  Item item;
  switch (lua_type(L, idx)) {
    case LUA_TNIL: break;
    case LUA_TBOOLEAN: item.type = lua_toboolean(L, idx) ? Type::True : Type::False; break;
    case LUA_TNUMBER:
      if (lua_isinteger(L, idx)) item.type = Type::Integer, item.integer = lua_tointeger(L, idx);
      else item.type = Type::Number, item.number = lua_tonumber(L, idx);
      break;
    case LUA_TSTRING: {
      size_t len = 0;
      const char* s = lua_tolstring(L, idx, &len);
      item.type = Type::String;
      item.integer = static_cast<int64_t>(strings_.size());
      strings_.emplace_back(s, len);
      break;
    }
    case LUA_TTABLE: {
      const void* address = lua_topointer(L, idx);
      auto it = seen_.find(address);
      if (it != seen_.end()) {  // shared or cyclic: the copy shares it the same way
        item.type = Type::TableRef;
        item.integer = it->second;
        break;
      }
      if (depth >= kMaxDepth || !lua_checkstack(L, 3)) {
        bad_type_ = "table nested too deep";
        return false;
      }
      const int64_t id = tables_++;
      seen_.emplace(address, id);
      items_.push_back({Type::TableBegin, id, 0});
      lua_pushnil(L);
      while (lua_next(L, idx)) {
        const int key = lua_type(L, -2), value = lua_type(L, -1);
        const bool plain_key = key == LUA_TNUMBER || key == LUA_TSTRING || key == LUA_TBOOLEAN || key == LUA_TTABLE;
        const bool plain_value = value != LUA_TFUNCTION && value != LUA_TUSERDATA && value != LUA_TLIGHTUSERDATA &&
                                 value != LUA_TTHREAD;
        if (!plain_key || !plain_value) {
          if (plain_only_) {
            bad_type_ = lua_typename(L, plain_key ? value : key);
            lua_pop(L, 2);
            return false;
          }
          lua_pop(L, 1);  // becomes nil: the pair is absent from the copy
          continue;
        }
        if (!RecordAt(L, lua_gettop(L) - 1, depth + 1) || !RecordAt(L, lua_gettop(L), depth + 1)) {
          lua_pop(L, 2);
          return false;
        }
        lua_pop(L, 1);
      }
      item.type = Type::TableEnd;
      break;
    }
    default:
      if (plain_only_) {
        bad_type_ = lua_typename(L, lua_type(L, idx));
        return false;
      }
      break;  // function, userdata, thread: nil
  }
  items_.push_back(item);
  return true;
}

void LuaTape::Replay(lua_State* L) const {
  luaL_checkstack(L, 4, "copying a Lua value");
  lua_createtable(L, 0, 0);  // table id → table, for shared and cyclic ones
  const int refs = lua_gettop(L);
  size_t pos = 0;
  if (items_.empty()) lua_pushnil(L);
  else ReplayAt(L, &pos, refs);
  lua_remove(L, refs);
}

void LuaTape::ReplayAt(lua_State* L, size_t* pos, int refs) const {
  const Item& item = items_[(*pos)++];
  switch (item.type) {
    case Type::Nil: lua_pushnil(L); break;
    case Type::False: lua_pushboolean(L, 0); break;
    case Type::True: lua_pushboolean(L, 1); break;
    case Type::Integer: lua_pushinteger(L, static_cast<lua_Integer>(item.integer)); break;
    case Type::Number: lua_pushnumber(L, item.number); break;
    case Type::String: {
      const std::string& s = strings_[static_cast<size_t>(item.integer)];
      lua_pushlstring(L, s.data(), s.size());
      break;
    }
    case Type::TableRef: lua_rawgeti(L, refs, item.integer + 1); break;
    case Type::TableBegin: {
      luaL_checkstack(L, 4, "copying a Lua value");
      lua_createtable(L, 0, 0);
      lua_pushvalue(L, -1);
      lua_rawseti(L, refs, item.integer + 1);
      while (items_[*pos].type != Type::TableEnd) {
        ReplayAt(L, pos, refs);
        ReplayAt(L, pos, refs);
        lua_rawset(L, -3);
      }
      ++*pos;
      break;
    }
    case Type::TableEnd: lua_pushnil(L); break;  // not reached: consumed by TableBegin
  }
}

}  // namespace essaim
