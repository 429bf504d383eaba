// Loading one experiment's loop-function libraries, as ARGoS: the one <loop_functions
// library="..."> names, or, with `label` alone, every library in ARGOS_PLUGIN_PATH. Each is
// checked for a Lua it cannot run against (lua_linkage.h) before any is opened; then they are
// opened together, as one group (library_group.h): they resolve symbols against each other, as
// ARGoS's global loading lets them, and never against another experiment's. Their
// REGISTER_LOOP_FUNCTIONS register their labels, tagged with the library. Libraries stay loaded
// for the process.
#pragma once
#include <string>
#include <vector>

namespace essaim {

/// Loads `paths` as one group; `loaded` gets their real paths, in order, without repeats.
/// False with `error` naming the library that fails.
bool LoadLoopFunctionLibraries(const std::vector<std::string>& paths, std::vector<std::string>* loaded,
                               std::string* error);

/// The shared libraries in the folders (or files) of ARGOS_PLUGIN_PATH, ':'-separated, in
/// order (a folder's sorted by name).
std::vector<std::string> PluginPathLibraries();

}  // namespace essaim
