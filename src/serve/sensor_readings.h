// What the live inspector shows of a robot whose controller is C++ (no Lua `robot` table to
// walk): the readings its declared sensors took this tick, from the RobotState the
// controller's ARGoS sensor objects read, keyed as the Lua robot table keys them.
#pragma once
#include "core/value.h"
#include "devices/robot_state.h"
#include "model/model.h"

namespace essaim {

/// The readings of `c`'s sensors in `r`, one entry per declared sensor (robot.<key>).
Value SensorReadingsValue(const ControllerDef& c, const RobotState& r);

/// What the inspector says of the controller: kind "lua" (its script) or "cpp" (its label,
/// library and a note that there are no Lua globals to show).
Value ControllerKindValue(const ControllerDef& c);

}  // namespace essaim
