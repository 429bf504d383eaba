// Plain Lua data copied between two lua_States (ARGoS loop functions reach a controller's
// state through CLuaController::GetLuaState()). A value is recorded from one state into a
// tape of C++ items with raw access only (no metamethod runs), then replayed into the
// other. Numbers, strings, booleans and tables (nested, shared and cyclic ones kept as
// such) are copied; functions, userdata and threads become nil.
#pragma once
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/value.h"

struct lua_State;

namespace essaim {

class LuaTape {
 public:
  /// Forgets the last value (keeps capacity).
  void Clear();
  /// Records the value at `idx` of `L`. With `plain_only`, a function, userdata or thread
  /// anywhere in it fails the record (`bad_type` names it); otherwise it records as nil.
  /// Also fails beyond kMaxDepth nested tables. Raises only Lua memory errors; callers
  /// keep the tape outside any frame a Lua error could unwind.
  bool Record(lua_State* L, int idx, bool plain_only, const char** bad_type);
  /// Pushes a copy of the recorded value onto `L` (raises on memory errors only).
  void Replay(lua_State* L) const;

  /// The recorded value as a tree with a JSON form: a table whose keys are 1..n is a list,
  /// any other a map (number and boolean keys as text). False with `error` for a cyclic
  /// table or a table used as a key; a table shared twice is written twice.
  bool ToValue(Value* out, std::string* error) const;

  static constexpr int kMaxDepth = 100;

 private:
  enum class Type : uint8_t { Nil, False, True, Integer, Number, String, TableBegin, TableEnd, TableRef };
  struct Item {
    Type type = Type::Nil;
    int64_t integer = 0;  // Integer value, string index or table id
    double number = 0;
  };
  bool RecordAt(lua_State* L, int idx, int depth);
  /// A table's pairs between TableBegin and TableEnd (`item`), or a TableRef to one seen.
  bool RecordTable(lua_State* L, int idx, int depth, Item* item);
  void ReplayAt(lua_State* L, size_t* pos, int refs) const;
  bool ValueAt(size_t* pos, std::vector<Value>* tables, Value* out, std::string* error) const;
  bool ValueTable(size_t* pos, std::vector<Value>* tables, Value* out, std::string* error) const;
  bool KeyText(size_t pos, std::string* key, std::string* error) const;
  std::vector<Item> items_;
  std::vector<std::string> strings_;
  std::unordered_map<const void*, int64_t> seen_;  // table address → id
  int64_t tables_ = 0;
  bool plain_only_ = false;
  const char* bad_type_ = nullptr;
};

/// A controller's global `name` as a value tree (what r:lua_global reads, for the Python
/// module), copied under a protected call. False with `error` when the state is closed, out
/// of memory, or the value has no JSON form.
bool LuaGlobalToValue(lua_State* C, const std::string& name, Value* out, std::string* error);

}  // namespace essaim
