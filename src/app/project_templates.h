// The files `essaim new NAME` writes (docs/testing.md): an experiment folder that runs and
// tests at once. Each template is a controller, loop functions with their metric and the test
// spec's expectations; the arena, the build files and the editor files are shared.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace essaim {

/// "empty", "aggregation", "foraging".
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
};
/// The template called `name`; nullptr when there is none.
const ProjectTemplate* FindProjectTemplate(const std::string& name);

struct ProjectContext {
  std::string name;         // the experiment's name: the folder and its files
  std::string templ;        // one of ProjectTemplateNames()
  std::string essaim_path;  // the binary the project's tests call
  std::string cmake_hint;   // a folder holding essaimConfig.cmake ("" = none found)
};

/// (relative path, content) of every file of the new project.
std::vector<std::pair<std::string, std::string>> ProjectFiles(const ProjectContext& context);

}  // namespace essaim
