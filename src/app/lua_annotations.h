// Editor support generated from the device table (docs/testing.md, "Editor"): annotations of
// robot.* and the loop functions' API for the Lua language server, and a luacheck
// configuration declaring the same globals. One annotation per DeviceType row, checked
// complete at compile time, so a new device cannot be left out.
#pragma once
#include <string>

namespace essaim {

/// A LuaLS definition file (---@meta): robot.* with every device, log/logerr, vector2/3,
/// quaternion, the loop functions' experiment table and entity handles.
std::string LuaLanguageServerDefs();
/// A .luacheckrc: Lua 5.4, the globals essaim gives controllers and loop functions (read-only,
/// with their fields), and the hook functions a script defines.
std::string LuacheckConfig();

}  // namespace essaim
