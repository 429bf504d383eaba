// Loading loop-function libraries, as ARGoS: the one <loop_functions library="..."> names,
// or, with `label` alone, every library in ARGOS_PLUGIN_PATH. Each is checked for a Lua it
// cannot run against (lua_linkage.h) before dlopen, then opened with its symbols global;
// its REGISTER_LOOP_FUNCTIONS registers its labels. Libraries stay loaded for the process.
#pragma once
#include <string>

namespace essaim {

/// Loads `path` (once per process); false with `error`.
bool LoadLoopFunctionLibrary(const std::string& path, std::string* error);

/// Loads every shared library in the folders (or files) of ARGOS_PLUGIN_PATH, ':'-separated;
/// false with `error` naming the first that fails.
bool LoadPluginPath(std::string* error);

}  // namespace essaim
