// "Did you mean" for a misspelled field of an API table (robot.*, experiment.*): Lua's own
// message names the field ("attempt to call a nil value (field 'set_all_colours')"), and the
// error handler, which runs before the stack unwinds, looks the name up among the table's
// keys. Nothing is done until an error happens, so a controller that makes no mistake pays
// nothing; and a missing field still reads as nil, as ARGoS gives it (`if robot.gripper`).
#pragma once
#include <string>
#include <vector>

struct lua_State;

namespace essaim {

/// A field absent from the API that the script may have meant: `absent` are the API's names
/// that can be missing on purpose (robot.gripper without a <footbot_gripper>) with why.
struct AbsentField {
  std::string name;
  std::string why;
};

/// The hint for error message `message` raised in `L`: "; did you mean robot.leds.set_all_colors?"
/// when the field it names is close to a key of global table `root` or of one of its tables,
/// the matching `absent` entry's `why` when the field is one of those; "" otherwise. Never raises.
std::string FieldHint(lua_State* L, const char* message, const char* root, const std::vector<AbsentField>& absent = {});

}  // namespace essaim
