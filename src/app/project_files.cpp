// The files of a new experiment folder (`essaim new`): the .argos file with its devices taken
// from the device table, the test spec, the build and ctest files, the editor files, a README.
#include <set>
#include <string>

#include "app/lua_annotations.h"
#include "app/project_templates.h"
#include "model/device_table.h"

namespace essaim {

namespace {
// The devices every template declares; the others are listed in a comment, ready to uncomment.
const std::set<DeviceType> kDeclared = {DeviceType::WheelsActuator,    DeviceType::LedsActuator,
                                        DeviceType::RabActuator,       DeviceType::ProximitySensor,
                                        DeviceType::PositioningSensor, DeviceType::RabSensor};

std::string Replaced(std::string text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

/// `<xml_name implementation="..." medium="..."/>` with the row's required attributes.
std::string DeviceElement(const DeviceRow& row) {
  std::string impl = row.implementations;
  std::string element = std::string("<") + row.xml_name + " implementation=\"" + impl.substr(0, impl.find(',')) + "\"";
  for (const DeviceAttr& a : row.attrs)
    if (a.required)
      element += std::string(" ") + a.name + "=\"" + (row.type == DeviceType::RabSensor ? "rab" : "leds") + "\"";
  return element + "/>";
}

/// The declared devices, each under its comment (what robot.<key> holds, or for C++ the
/// control interface); the ground sensors only over a floor (ARGoS refuses them without one).
std::string DeviceLines(bool sensors, bool floor, bool cpp) {
  std::string declared, others;
  for (const DeviceRow& row : kDeviceRows) {
    if (row.is_sensor != sensors || !row.supported) continue;
    const std::string doc = cpp ? CppDeviceDoc(row.xml_name, row.is_sensor) : row.doc;
    if (kDeclared.count(row.type) || (floor && row.type == DeviceType::MotorGroundSensor))
      declared += "        <!-- " + doc + " -->\n        " + DeviceElement(row) + "\n";
    else
      others += "             " + DeviceElement(row) + "\n";
  }
  return declared + "        <!-- more (essaim devices describes each):\n" + others + "        -->\n";
}

const char* kFloor =
    "    <!-- the floor's colours: floor_color(x, y) of the loop functions, sampled once at start -->\n"
    "    <floor id=\"floor\" source=\"loop_functions\" pixels_per_meter=\"50\"/>\n";

}  // namespace

const char* const kProjectGitignore = "build/\nruns/\nessaim-test/\n*.junit.xml\n";

namespace {
// The .argos file's and the spec's parts of a project of Lua scripts.
const ProjectLayout kLuaLayout = {
    "     Run it:  essaim run @NAME@.argos        Test it:  ctest  (or essaim test @NAME@.test.toml)",
    R"(    <lua_controller id="@NAME@">
      <actuators>
@ACTUATORS@      </actuators>
      <sensors>
@SENSORS@      </sensors>
      <!-- robot.params: every attribute but script, as strings -->
      <params script="@NAME@.lua" speed="10"/>
    </lua_controller>
)",
    R"(  <!-- the loop functions: the experiment's metric (metrics.json) -->
  <loop_functions script="@NAME@_loop.lua"/>
)",
    "@NAME@.argos"};

const char* kArgos = R"(<?xml version="1.0" ?>
<!-- @NAME@ (essaim new @NAME@ --template @TEMPLATE@): @ABOUT@.
@RUN@ -->
<argos-configuration>
  <framework>
    <system threads="0"/>
    <!-- length in seconds; 10 ticks a second -->
    <experiment length="60" ticks_per_second="10" random_seed="1"/>
  </framework>

  <controllers>
@CONTROLLER@  </controllers>

@LOOP_FUNCTIONS@
  <arena size="4.2,4.2,1" center="0,0,0.5">
@FLOOR@    <box id="wall_north" size="4,0.1,0.5" movable="false"><body position="0,2.05,0" orientation="0,0,0"/></box>
    <box id="wall_south" size="4,0.1,0.5" movable="false"><body position="0,-2.05,0" orientation="0,0,0"/></box>
    <box id="wall_east" size="0.1,4,0.5" movable="false"><body position="2.05,0,0" orientation="0,0,0"/></box>
    <box id="wall_west" size="0.1,4,0.5" movable="false"><body position="-2.05,0,0" orientation="0,0,0"/></box>
    <!-- the swarm: 10 foot-bots placed at random, ids fb0..fb9 -->
    <distribute>
      <position method="uniform" min="-1.8,-1.8,0" max="1.8,1.8,0"/>
      <orientation method="uniform" min="0,0,0" max="360,0,0"/>
      <entity quantity="10" max_trials="100">
        <foot-bot id="fb" rab_range="1.5"><controller config="@NAME@"/></foot-bot>
      </entity>
    </distribute>
  </arena>

  <physics_engines><dynamics2d id="dyn2d"/></physics_engines>
  <media>
    <range_and_bearing id="rab"/>
    <led id="leds"/>
  </media>
</argos-configuration>
)";

const char* kSpec = R"(# The behaviour test of @NAME@ (docs/testing.md): `essaim test @NAME@.test.toml`, or `ctest`.
experiment = "@EXPERIMENT@"
ticks = @TICKS@
seeds = 10            # seeds 1..10, run side by side (essaim test -j N)
timeout = 300         # seconds: ctest's limit for the whole test
labels = ["behaviour"]
expect = [
@EXPECT@]

# [set]: overrides for every run, as essaim run --set PATH=VALUE
# [set]
# "arena.distribute.entity.quantity" = 20
)";

const char* kCMakeLists = R"(# @NAME@'s tests under ctest:  cmake -S . -B build && ctest --test-dir build
# (the CTestTestfile.cmake beside this file lets a plain `ctest` here run them without CMake)
cmake_minimum_required(VERSION 3.18)
project(@NAME@ NONE)
enable_testing()
find_package(essaim REQUIRED@HINTS@)
essaim_add_test(NAME @NAME@_behaviour SPEC ${CMAKE_CURRENT_SOURCE_DIR}/@NAME@.test.toml)
)";

const char* kCTestFile =
    R"(# Written by `essaim new` so that `ctest` runs in this folder at once; CMakeLists.txt declares
# the same test for a build folder. Its essaim is the one that made the project.
add_test(@NAME@_behaviour "@ESSAIM@" "test" "@NAME@.test.toml" "--junit" "@NAME@.junit.xml")
set_tests_properties(@NAME@_behaviour PROPERTIES TIMEOUT "300" LABELS "essaim;behaviour")
)";

const char* kLuarc = R"({
  "$schema": "https://raw.githubusercontent.com/LuaLS/vscode-lua/master/setting/schema.json",
  "runtime.version": "Lua 5.4",
  "workspace.library": ["types"],
  "diagnostics.globals": ["init", "step", "reset", "destroy", "pre_step", "post_step", "is_experiment_finished",
                          "post_experiment", "floor_color"]
}
)";

const char* kReadme = R"(# @NAME@

What happens: @ABOUT@ (made by `essaim new @NAME@ --template @TEMPLATE@`).

| file | what |
|---|---|
| `@NAME@.argos` | the experiment: arena, walls, 10 foot-bots, their devices |
| `@NAME@.lua` | the controller: `init`, `step`, `reset`, `destroy` |
| `@NAME@_loop.lua` | the loop functions: the metric written into `metrics.json` |
| `@NAME@.test.toml` | the behaviour test: seeds, ticks, expectations |
| `CMakeLists.txt`, `CTestTestfile.cmake` | the test under ctest |
| `.luarc.json`, `types/essaim.lua`, `.luacheckrc` | editor completion of `robot.*`, and luacheck |

A run writes into `runs/@NAME@-SEED/`; the test's runs go into `essaim-test/`.

    essaim run @NAME@.argos      # one run
    ctest --output-on-failure    # the behaviour test: essaim test @NAME@.test.toml
    luacheck .                   # the scripts against essaim's globals

Regenerate the editor files after an upgrade of essaim:
`essaim devices --lua-defs > types/essaim.lua` and `essaim devices --luacheck > .luacheckrc`.
)";

/// The layout's parts first: they hold placeholders of their own.
std::string WithLayout(const std::string& text, const ProjectLayout& layout) {
  std::string out = Replaced(text, "@RUN@", layout.run);
  out = Replaced(out, "@CONTROLLER@", layout.controller);
  out = Replaced(out, "@LOOP_FUNCTIONS@", layout.loop_functions);
  return Replaced(out, "@EXPERIMENT@", layout.experiment);
}
}  // namespace

std::string FilledProjectText(const std::string& text, const ProjectContext& c, const ProjectTemplate& t) {
  std::string out = WithLayout(text, t.cpp ? kCppLayout : kLuaLayout);
  out = Replaced(out, "@NAME@", c.name);
  out = Replaced(out, "@TEMPLATE@", c.templ);
  out = Replaced(out, "@ABOUT@", t.about);
  out = Replaced(out, "@TICKS@", t.ticks);
  out = Replaced(out, "@FLOOR@", t.uses_floor ? kFloor : "");
  out = Replaced(out, "@EXPECT@", t.expectations);
  out = Replaced(out, "@ESSAIM@", c.essaim_path);
  out = Replaced(out, "@HINTS@", c.cmake_hint.empty() ? "" : " HINTS \"" + c.cmake_hint + "\"");
  out = Replaced(out, "@ARGOS_PREFIX@", c.argos_prefix);
  out = Replaced(out, "@ACTUATORS@", DeviceLines(false, t.uses_floor, t.cpp));
  return Replaced(out, "@SENSORS@", DeviceLines(true, t.uses_floor, t.cpp));
}

std::string ArgosFileText(const ProjectContext& c, const ProjectTemplate& t) { return FilledProjectText(kArgos, c, t); }

std::string SpecText(const ProjectContext& c, const ProjectTemplate& t) { return FilledProjectText(kSpec, c, t); }

std::vector<std::pair<std::string, std::string>> ProjectFiles(const ProjectContext& c) {
  const ProjectTemplate& t = *FindProjectTemplate(c.templ);
  if (t.cpp) return CppProjectFiles(c, t);
  const std::string& n = c.name;
  auto filled = [&](const char* text) { return FilledProjectText(text, c, t); };
  return {{n + ".argos", ArgosFileText(c, t)},
          {n + ".lua", filled(t.controller)},
          {n + "_loop.lua", filled(t.loop)},
          {n + ".test.toml", SpecText(c, t)},
          {"CMakeLists.txt", filled(kCMakeLists)},
          {"CTestTestfile.cmake", filled(kCTestFile)},
          {".luarc.json", kLuarc},
          {"types/essaim.lua", LuaLanguageServerDefs()},
          {".luacheckrc", LuacheckConfig() + "exclude_files = {\"types/*.lua\", \"build/**\"}\n"},
          {".gitignore", kProjectGitignore},
          {"README.md", filled(kReadme)}};
}

}  // namespace essaim
