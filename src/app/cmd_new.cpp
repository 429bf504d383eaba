// `essaim new NAME [--template T]`: a new experiment folder that runs and tests at once
// (project_templates.cpp, project_files.cpp; docs/testing.md).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <regex>
#include <set>

#include "app/commands.h"
#include "app/project_templates.h"

namespace essaim {

namespace {
namespace fs = std::filesystem;

struct NewArgs {
  std::string name;
  std::string templ = "empty";
};

/// The folder holding essaimConfig.cmake for this binary: beside it (a build folder) or
/// PREFIX/lib/cmake/essaim (an install); "" when neither has one.
std::string CMakeHint(const fs::path& binary) {
  for (const fs::path& dir : {binary.parent_path(), binary.parent_path().parent_path() / "lib/cmake/essaim"})
    if (fs::exists(dir / "essaimConfig.cmake")) return dir.lexically_normal().string();
  return "";
}

/// The folder holding lib/pkgconfig/argos3_simulator.pc for this binary: build/argos3-sdk
/// beside it (a build folder) or PREFIX (an install); "" when neither has one.
std::string ArgosPrefix(const fs::path& binary) {
  for (const fs::path& dir : {binary.parent_path() / "argos3-sdk", binary.parent_path().parent_path()})
    if (fs::exists(dir / "lib/pkgconfig/argos3_simulator.pc")) return dir.lexically_normal().string();
  return "";
}

/// The target names CMake keeps for itself: the C++ template's library cannot take one.
bool IsCMakeReservedName(const std::string& name) {
  static const std::set<std::string> reserved = {
      "all",           "clean",  "help",      "install",    "test",      "package", "package_source", "edit_cache",
      "rebuild_cache", "depend", "ALL_BUILD", "ZERO_CHECK", "RUN_TESTS", "INSTALL", "PACKAGE"};
  return reserved.count(name) > 0;
}

/// What to type next.
void PrintNext(const NewArgs& args) {
  const char* n = args.name.c_str();
  std::printf("essaim new: %s/ made from the '%s' template. Next:\n", n, args.templ.c_str());
  if (args.templ == "cpp")
    std::printf(
        "  cd %s && ctest    (configures and builds into build/, then tests)\n"
        "  essaim run experiments/%s.argos\n",
        n, n);
  else
    std::printf("  cd %s && essaim run %s.argos && ctest\n", n, n);
}

int New(const NewArgs& args) {
  if (!std::regex_match(args.name, std::regex("[A-Za-z][A-Za-z0-9_-]*"))) {
    std::fprintf(stderr, "essaim new: '%s': a name is a letter, then letters, digits, _ or -\n", args.name.c_str());
    return kExitBadInput;
  }
  if (args.templ == "cpp" && IsCMakeReservedName(args.name)) {
    std::fprintf(stderr, "essaim new: '%s' is a target name CMake reserves; the C++ template names its library so\n",
                 args.name.c_str());
    return kExitBadInput;
  }
  fs::path folder = args.name;
  std::error_code ec;
  if (fs::exists(folder, ec)) {
    std::fprintf(stderr, "essaim new: %s already exists; nothing written\n", args.name.c_str());
    return kExitBadInput;
  }
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  ProjectContext context{args.name, args.templ, self.string(), CMakeHint(self), ArgosPrefix(self)};
  for (const auto& [path, text] : ProjectFiles(context)) {
    fs::create_directories((folder / path).parent_path(), ec);
    std::ofstream out(folder / path, std::ios::binary);
    out << text;
    if (!out.flush()) {
      std::fprintf(stderr, "essaim new: cannot write %s\n", (folder / path).c_str());
      return kExitRunFailed;
    }
  }
  PrintNext(args);
  return kExitOk;
}
}  // namespace

CommandMain AddNewCommand(CLI::App& app) {
  auto args = std::make_shared<NewArgs>();
  CLI::App* sub = app.add_subcommand("new", "make a new experiment folder: .argos, controller, loop functions, test");
  sub->add_option("NAME", args->name, "the experiment's name: its folder and files")->required();
  sub->add_option("--template", args->templ,
                  "what the robots do: empty, aggregation, foraging (Lua scripts), or cpp (an ARGoS C++ controller and "
                  "loop functions, built with CMake)")
      ->check(CLI::IsMember(ProjectTemplateNames()))
      ->capture_default_str();
  sub->footer("Examples:\n  essaim new demo --template aggregation\n  essaim new swarm --template cpp");
  return [args] { return New(*args); };
}

}  // namespace essaim
