// Loading one experiment's libraries (argos_host.h says which), as ARGoS loads them. Each is
// checked for a Lua it cannot run against (lua_linkage.h) before any is opened; then they are
// opened together, as one group (library_group.h): they resolve symbols against each other, as
// ARGoS's global loading lets them, and never against another experiment's. Their
// REGISTER_LOOP_FUNCTIONS and REGISTER_CONTROLLER register their labels, tagged with the library. Libraries stay loaded
// for the process.
#pragma once
#include <string>
#include <vector>

namespace essaim {

/// Loads `paths` as one group; `loaded` gets their real paths, in order, without repeats.
/// False with `error` naming the library that fails.
bool LoadArgosLibraries(const std::vector<std::string>& paths, std::vector<std::string>* loaded, std::string* error);

/// The shared libraries in the folders (or files) of ARGOS_PLUGIN_PATH, ':'-separated, in
/// order (a folder's sorted by name).
std::vector<std::string> PluginPathLibraries();

}  // namespace essaim
