// library="..." of C++ loop functions and controllers, found as ARGoS's CDynamicLoading finds
// it: an absolute path as written; a relative one in each folder of ARGOS_PLUGIN_PATH, then
// in "." (the folder essaim was started in); each as written, then with ".so". essaim then
// tries beside the .argos file too, where its own examples keep their libraries.
#include <cstdlib>
#include <string>
#include <vector>

#include "core/paths.h"
#include "core/strings.h"
#include "model/xml_loader_impl.h"

namespace essaim::xml_loader {

namespace {
// The folders a relative library name is tried in, in order.
std::vector<std::string> LibraryFolders(const std::string& working_dir, const std::string& argos_dir) {
  std::vector<std::string> folders;
  if (const char* env = std::getenv("ARGOS_PLUGIN_PATH"))
    for (const std::string& dir : Split(env, ':'))
      if (!dir.empty()) folders.push_back(dir);
  folders.push_back(working_dir);
  if (argos_dir != working_dir) folders.push_back(argos_dir);
  return folders;
}
}  // namespace

std::string Loader::ResolveLibrary(const XMLElement* e, const std::string& library) {
  std::vector<std::string> bases;
  if (library[0] == '/')
    bases.push_back(library);
  else
    for (const std::string& dir : LibraryFolders(options_.working_dir, dir_.empty() ? "." : dir_))
      bases.push_back(dir == "." ? "./" + library : JoinPath(dir, library));
  std::string tried;
  for (const std::string& base : bases)
    for (const std::string& candidate : {base, base + ".so"}) {
      if (FileExists(candidate)) return candidate;
      tried += (tried.empty() ? "" : ", ") + candidate;
    }
  Error(e, "library '" + library + "' not found; tried " + tried +
               (std::getenv("ARGOS_PLUGIN_PATH") ? "" : " (ARGOS_PLUGIN_PATH is not set)"));
  return "";
}

}  // namespace essaim::xml_loader
