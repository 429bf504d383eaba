#include "lua/loop/lua_copy.h"

#include <algorithm>
#include <lua.hpp>

#include "core/strings.h"

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
    case LUA_TNIL:
      break;
    case LUA_TBOOLEAN:
      item.type = lua_toboolean(L, idx) ? Type::True : Type::False;
      break;
    case LUA_TNUMBER:
      if (lua_isinteger(L, idx))
        item.type = Type::Integer, item.integer = lua_tointeger(L, idx);
      else
        item.type = Type::Number, item.number = lua_tonumber(L, idx);
      break;
    case LUA_TSTRING: {
      size_t len = 0;
      const char* s = lua_tolstring(L, idx, &len);
      item.type = Type::String;
      item.integer = static_cast<int64_t>(strings_.size());
      strings_.emplace_back(s, len);
      break;
    }
    case LUA_TTABLE:
      if (!RecordTable(L, idx, depth, &item)) return false;
      break;
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

bool LuaTape::RecordTable(lua_State* L, int idx, int depth, Item* item) {
  const void* address = lua_topointer(L, idx);
  auto it = seen_.find(address);
  if (it != seen_.end()) {  // shared or cyclic: the copy shares it the same way
    item->type = Type::TableRef;
    item->integer = it->second;
    return true;
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
    const bool plain_value =
        value != LUA_TFUNCTION && value != LUA_TUSERDATA && value != LUA_TLIGHTUSERDATA && value != LUA_TTHREAD;
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
  item->type = Type::TableEnd;
  return true;
}

void LuaTape::Replay(lua_State* L) const {
  luaL_checkstack(L, 4, "copying a Lua value");
  lua_createtable(L, 0, 0);  // table id → table, for shared and cyclic ones
  const int refs = lua_gettop(L);
  size_t pos = 0;
  if (items_.empty())
    lua_pushnil(L);
  else
    ReplayAt(L, &pos, refs);
  lua_remove(L, refs);
}

void LuaTape::ReplayAt(lua_State* L, size_t* pos, int refs) const {
  const Item& item = items_[(*pos)++];
  switch (item.type) {
    case Type::Nil:
      lua_pushnil(L);
      break;
    case Type::False:
      lua_pushboolean(L, 0);
      break;
    case Type::True:
      lua_pushboolean(L, 1);
      break;
    case Type::Integer:
      lua_pushinteger(L, static_cast<lua_Integer>(item.integer));
      break;
    case Type::Number:
      lua_pushnumber(L, item.number);
      break;
    case Type::String: {
      const std::string& s = strings_[static_cast<size_t>(item.integer)];
      lua_pushlstring(L, s.data(), s.size());
      break;
    }
    case Type::TableRef:
      lua_rawgeti(L, refs, item.integer + 1);
      break;
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
    case Type::TableEnd:
      lua_pushnil(L);
      break;  // not reached: consumed by TableBegin
  }
}

bool LuaTape::ToValue(Value* out, std::string* error) const {
  if (items_.empty()) return *out = Value(), true;
  std::vector<Value> tables(static_cast<size_t>(tables_));
  size_t pos = 0;
  return ValueAt(&pos, &tables, out, error);
}

bool LuaTape::ValueAt(size_t* pos, std::vector<Value>* tables, Value* out, std::string* error) const {
  const Item& item = items_[(*pos)++];
  switch (item.type) {
    case Type::Nil:
      *out = Value();
      return true;
    case Type::False:
      *out = Value::OfBool(false);
      return true;
    case Type::True:
      *out = Value::OfBool(true);
      return true;
    case Type::Integer:
      *out = Value::OfInteger(item.integer);
      return true;
    case Type::Number:
      *out = Value::OfNumber(item.number);
      return true;
    case Type::String:
      *out = Value::OfString(strings_[static_cast<size_t>(item.integer)]);
      return true;
    case Type::TableRef:
      *out = (*tables)[static_cast<size_t>(item.integer)];
      if (out->IsNull()) return *error = "a table that contains itself has no JSON form", false;
      return true;
    case Type::TableBegin:
      return ValueTable(pos, tables, out, error);
    case Type::TableEnd:
      break;  // not reached: consumed by ValueTable
  }
  return *error = "malformed copy", false;
}

bool LuaTape::ValueTable(size_t* pos, std::vector<Value>* tables, Value* out, std::string* error) const {
  const size_t id = static_cast<size_t>(items_[*pos - 1].integer);
  Value object = Value::EmptyMap();
  std::vector<std::pair<int64_t, Value>> numbered;  // integer keys, to see whether it is an array
  while (items_[*pos].type != Type::TableEnd) {
    std::string key;
    const Item& k = items_[*pos];
    if (!KeyText((*pos)++, &key, error)) return false;
    Value value;
    if (!ValueAt(pos, tables, &value, error)) return false;
    if (k.type == Type::Integer) numbered.emplace_back(k.integer, value);
    object.Set(key, std::move(value));
  }
  ++*pos;
  std::sort(numbered.begin(), numbered.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  bool array = !numbered.empty() && numbered.size() == object.map.size();
  for (size_t i = 0; array && i < numbered.size(); ++i) array = numbered[i].first == static_cast<int64_t>(i + 1);
  if (array) {
    Value list = Value::EmptyList();
    for (auto& kv : numbered) list.list.push_back(std::move(kv.second));
    object = std::move(list);
  }
  (*tables)[id] = object;
  *out = std::move(object);
  return true;
}

bool LuaTape::KeyText(size_t pos, std::string* key, std::string* error) const {
  const Item& k = items_[pos];
  switch (k.type) {
    case Type::String:
      *key = strings_[static_cast<size_t>(k.integer)];
      return true;
    case Type::Integer:
      *key = std::to_string(k.integer);
      return true;
    case Type::Number:
      *key = FormatDouble(k.number);
      return true;
    case Type::False:
      *key = "false";
      return true;
    case Type::True:
      *key = "true";
      return true;
    default:
      return *error = "a table used as a key has no JSON form", false;
  }
}

namespace {
struct GlobalJob {
  LuaTape* tape;
  const char* name;
  bool ok;
};

int RecordGlobal(lua_State* C) {
  auto* job = static_cast<GlobalJob*>(lua_touserdata(C, 1));
  lua_rawgeti(C, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  lua_pushstring(C, job->name);
  lua_rawget(C, -2);
  job->ok = job->tape->Record(C, -1, false, nullptr);
  return 0;
}
}  // namespace

bool LuaGlobalToValue(lua_State* C, const std::string& name, Value* out, std::string* error) {
  if (!C) return *error = "its controller is not running (no script, or stopped at its memory limit)", false;
  LuaTape tape;
  GlobalJob job{&tape, name.c_str(), false};
  if (!lua_checkstack(C, 3)) return *error = "its Lua state is out of memory", false;
  const int top = lua_gettop(C);
  lua_pushcfunction(C, RecordGlobal);
  lua_pushlightuserdata(C, &job);
  const bool called = lua_pcall(C, 1, 0, 0) == LUA_OK;
  lua_settop(C, top);
  if (!called || !job.ok) return *error = "its Lua state is out of memory or the value is nested too deep", false;
  return tape.ToValue(out, error);
}

}  // namespace essaim
