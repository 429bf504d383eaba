// The files `essaim new NAME` writes (docs/testing.md): an experiment folder that runs and
// tests at once. Each template is a controller, loop functions with their metric and the test
// spec's expectations; the arena, the build files and the editor files are shared.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace essaim {

/// "empty", "aggregation", "foraging", "cpp".
const std::vector<std::string>& ProjectTemplateNames();

/// What differs between templates (project_templates.cpp): the scripts and the expectations.
struct ProjectTemplate {
  const char* name;
  const char* controller;    // NAME.lua
  const char* loop;          // NAME_loop.lua
  const char* expectations;  // the spec's expect = [...] lines
  const char* ticks;         // the spec's ticks
  const char* about;         // one line for the README and the .argos file
  bool uses_floor = false;   // the loop functions colour the floor (floor_color)
  bool cpp = false;          // C++ sources laid out as argos3-examples (project_cpp_files.cpp)
};
/// The template called `name`; nullptr when there is none.
const ProjectTemplate* FindProjectTemplate(const std::string& name);

struct ProjectContext {
  std::string name;          // the experiment's name: the folder and its files
  std::string templ;         // one of ProjectTemplateNames()
  std::string essaim_path;   // the binary the project's tests call
  std::string cmake_hint;    // a folder holding essaimConfig.cmake ("" = none found)
  std::string argos_prefix;  // the folder holding lib/pkgconfig/argos3_simulator.pc ("" = none found)
};

/// (relative path, content) of every file of the new project.
std::vector<std::pair<std::string, std::string>> ProjectFiles(const ProjectContext& context);

/// What differs in the .argos file and the spec between Lua and C++ projects.
struct ProjectLayout {
  const char* run;             // the .argos file's opening comment: how to run and test it
  const char* controller;      // the <controllers> entry
  const char* loop_functions;  // the <loop_functions> element, with its comment
  const char* experiment;      // the spec's experiment = "...", relative to the spec
};
extern const ProjectLayout kCppLayout;  // project_cpp_files.cpp
extern const char* const kProjectGitignore;

/// `text` with @NAME@, @ABOUT@, @ACTUATORS@ and the other placeholders filled in.
std::string FilledProjectText(const std::string& text, const ProjectContext& c, const ProjectTemplate& t);
std::string ArgosFileText(const ProjectContext& c, const ProjectTemplate& t);
std::string SpecText(const ProjectContext& c, const ProjectTemplate& t);

/// The files of the "cpp" template (project_cpp_files.cpp), and its sources
/// (project_cpp_sources.cpp: @CLASS@ and @GUARD@ still to fill).
std::vector<std::pair<std::string, std::string>> CppProjectFiles(const ProjectContext& c, const ProjectTemplate& t);
/// The control interface a C++ controller gets for a device: "CCI_LEDsActuator: SetAllColors,
/// SetSingleColor (13 LEDs)" (project_cpp_files.cpp).
std::string CppDeviceDoc(const std::string& xml_name, bool sensor);
extern const char* const kCppControllerHeader;
extern const char* const kCppController;
extern const char* const kCppLoopHeader;
extern const char* const kCppLoop;

}  // namespace essaim
