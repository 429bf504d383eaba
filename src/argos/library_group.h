// One experiment's loop-function libraries, loaded together and apart from every other
// experiment's. ARGoS opens each library RTLD_GLOBAL: the experiment's libraries resolve
// symbols against each other (a class of one used by another, a symbol left undefined in one
// and defined in another), but so would a later experiment's, binding its `new CFoo` to an
// earlier library's CFoo. Here the libraries are opened by one dlopen(RTLD_NOW | RTLD_LOCAL) of
// a "group": a tiny shared object, made in memory, whose only content is the libraries' paths
// as DT_NEEDED entries. glibc relocates every object a dlopen loads against the global scope
// and that dlopen's search list (the group and all it needs), so the libraries see each other
// and nothing of another group.
#pragma once
#include <string>
#include <vector>

namespace essaim {

/// The bytes of a 64-bit ELF shared object, for the machine this process runs on, whose
/// dynamic section needs `libraries` (absolute paths), in order, and holds nothing else.
std::string GroupObject(const std::vector<std::string>& libraries);

/// Loads `libraries` (absolute paths) as one group; a set loaded before is not loaded again
/// (its libraries, as all loaded ones, stay for the life of the process). False with dlerror's
/// message in `error`.
bool OpenLibraryGroup(const std::vector<std::string>& libraries, std::string* error);

}  // namespace essaim
