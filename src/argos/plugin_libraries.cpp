#include "argos/plugin_libraries.h"

#include <dirent.h>
#include <dlfcn.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <set>
#include <vector>

#include "argos/argos_session.h"
#include "argos/lua_linkage.h"

namespace essaim {

namespace {
std::mutex loading;
std::set<std::string>& Loaded() {
  static std::set<std::string> loaded;
  return loaded;
}

// The folder of the ARGoS API library this process runs (libargos3core_simulator.so).
std::string ApiFolder() {
  Dl_info info;
  if (!dladdr(reinterpret_cast<void*>(&ArgosApiVersion), &info) || !info.dli_fname) return "";
  const std::string path = info.dli_fname;
  const size_t slash = path.rfind('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

// ARGoS splits its API over several libraries that projects link by name; essaim's are
// aliases of the one API library, opened here so that a plugin finds them whatever its
// run path says.
void OpenApiAliases() {
  static const bool opened = [] {
    const std::string folder = ApiFolder();
    for (const char* name : {"libargos3plugin_simulator_entities.so", "libargos3plugin_simulator_footbot.so",
                             "libargos3plugin_simulator_media.so"})
      dlopen((folder + "/" + name).c_str(), RTLD_NOW | RTLD_GLOBAL);
    return true;
  }();
  (void)opened;
}

std::string RealPath(const std::string& path) {
  char* real = realpath(path.c_str(), nullptr);
  const std::string out = real ? real : path;
  std::free(real);
  return out;
}
}  // namespace

bool LoadLoopFunctionLibrary(const std::string& path, std::string* error) {
  std::lock_guard<std::mutex> lock(loading);
  const std::string real = RealPath(path);
  if (Loaded().count(real)) return true;
  LuaLinkage linkage;
  if (!ReadLuaLinkage(path, &linkage, error)) return false;
  *error = LuaMismatch(path, linkage);
  if (!error->empty()) return false;
  OpenApiAliases();
  if (!dlopen(real.c_str(), RTLD_NOW | RTLD_GLOBAL)) {
    const char* why = dlerror();
    *error = "cannot load loop-function library " + path + ": " + (why ? why : "unknown error") +
             " (a library built against ARGoS itself, or another essaim, must be rebuilt against this essaim)";
    return false;
  }
  Loaded().insert(real);
  return true;
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

bool LoadPluginPath(std::string* error) {
  const char* env = std::getenv("ARGOS_PLUGIN_PATH");
  const std::string paths = env ? env : "";
  size_t start = 0;
  while (start <= paths.size()) {
    size_t end = paths.find(':', start);
    if (end == std::string::npos) end = paths.size();
    for (const std::string& library : LibrariesIn(paths.substr(start, end - start)))
      if (!LoadLoopFunctionLibrary(library, error)) return false;
    start = end + 1;
  }
  return true;
}

}  // namespace essaim
