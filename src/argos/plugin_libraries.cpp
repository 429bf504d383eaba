#include "argos/plugin_libraries.h"

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>

#include "argos/library_group.h"
#include "argos/lua_linkage.h"

namespace essaim {

namespace {
std::string RealPath(const std::string& path) {
  char* real = realpath(path.c_str(), nullptr);
  const std::string out = real ? real : path;
  std::free(real);
  return out;
}

// Refuses, before it is loaded, a library that would load ARGoS's own libraries (the names
// it was linked against: essaim's links record essaim's soname) or run against another Lua.
bool CheckLinkage(const std::string& path, std::string* error) {
  LuaLinkage linkage;
  if (!ReadLuaLinkage(path, &linkage, error)) return false;
  for (const std::string& needed : linkage.needed)
    if (needed.rfind("libargos3", 0) == 0)
      return *error = path + " was built against ARGoS itself or an older essaim (it needs " + needed +
                      "): rebuild it against this essaim's ARGoS API",
             false;
  *error = LuaMismatch(path, linkage);
  return error->empty();
}
}  // namespace

bool LoadArgosLibraries(const std::vector<std::string>& paths, std::vector<std::string>* loaded, std::string* error) {
  loaded->clear();
  for (const std::string& path : paths) {
    if (!CheckLinkage(path, error)) return false;
    const std::string real = RealPath(path);
    if (std::find(loaded->begin(), loaded->end(), real) == loaded->end()) loaded->push_back(real);
  }
  if (OpenLibraryGroup(*loaded, error)) return true;
  std::string names;
  for (const std::string& path : paths) names += (names.empty() ? "" : ", ") + path;
  *error = (paths.size() == 1 ? "cannot load library " : "cannot load the libraries ") + names + ": " + *error +
           " (a library built against ARGoS itself, or another essaim, must be rebuilt against this essaim)";
  return false;
}

namespace {
// The shared libraries in `folder` (or `folder` itself when it is a file), sorted.
std::vector<std::string> LibrariesIn(const std::string& folder) {
  std::vector<std::string> out;
  struct stat info;
  if (stat(folder.c_str(), &info) != 0) return out;
  if (!S_ISDIR(info.st_mode)) return {folder};
  if (DIR* dir = opendir(folder.c_str())) {
    while (const dirent* entry = readdir(dir)) {
      const std::string name = entry->d_name;
      if (name.size() > 3 && name.compare(name.size() - 3, 3, ".so") == 0) out.push_back(folder + "/" + name);
    }
    closedir(dir);
  }
  std::sort(out.begin(), out.end());
  return out;
}
}  // namespace

std::vector<std::string> PluginPathLibraries() {
  const char* env = std::getenv("ARGOS_PLUGIN_PATH");
  const std::string paths = env ? env : "";
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= paths.size()) {
    size_t end = paths.find(':', start);
    if (end == std::string::npos) end = paths.size();
    for (const std::string& library : LibrariesIn(paths.substr(start, end - start))) out.push_back(library);
    start = end + 1;
  }
  return out;
}

}  // namespace essaim
