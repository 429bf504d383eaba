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

  static constexpr int kMaxDepth = 100;

 private:
  enum class Type : uint8_t { Nil, False, True, Integer, Number, String, TableBegin, TableEnd, TableRef };
  struct Item {
    Type type = Type::Nil;
    int64_t integer = 0;  // Integer value, string index or table id
    double number = 0;
  };
  bool RecordAt(lua_State* L, int idx, int depth);
  void ReplayAt(lua_State* L, size_t* pos, int refs) const;
  std::vector<Item> items_;
  std::vector<std::string> strings_;
  std::unordered_map<const void*, int64_t> seen_;  // table address → id
  int64_t tables_ = 0;
  bool plain_only_ = false;
  const char* bad_type_ = nullptr;
};

}  // namespace essaim
