// The files of `essaim new NAME --template cpp` (docs/cpp-controllers.md): an ARGoS C++ project
// laid out as argos3-examples is, its top CMakeLists.txt finding ARGoS through pkg-config in
// the essaim that made it, the experiment in experiments/, the test spec at the top.
#include <cctype>
#include <string>

#include "app/project_templates.h"

namespace essaim {

const ProjectLayout kCppLayout = {
    "     Build:   cmake -S . -B build && cmake --build build   (in the project's folder)\n"
    "     Run it:  essaim run experiments/@NAME@.argos        Test it:  ctest  (or essaim test @NAME@.test.toml)",
    R"(    <!-- the tag is the label of REGISTER_CONTROLLER; library: found as ARGoS finds it (in
         ARGOS_PLUGIN_PATH's folders, then the folder essaim runs in), then beside this file -->
    <@NAME@_controller id="@NAME@" library="build/controllers/@NAME@/lib@NAME@">
      <actuators>
@ACTUATORS@      </actuators>
      <sensors>
@SENSORS@      </sensors>
      <!-- Init(t_node) gets this element: GetNodeAttributeOrDefault(t_node, "speed", ...) -->
      <params speed="10" arrived="0.5"/>
    </@NAME@_controller>
)",
    R"(  <!-- the loop functions: the experiment's metric, a file the test reads (files/spread.csv) -->
  <loop_functions library="build/loop_functions/@NAME@_loop_functions/lib@NAME@_loop_functions"
                  label="@NAME@_loop_functions">
    <params output="spread.csv" every="50"/>
  </loop_functions>
)",
    "experiments/@NAME@.argos"};

namespace {
const char* kTopCMakeLists =
    R"(# @NAME@: an ARGoS C++ controller and loop functions (essaim new @NAME@ --template cpp).
#   cmake -S . -B build && cmake --build build      the libraries, into build/ (the .argos names them so)
#   essaim run experiments/@NAME@.argos             one run, from this folder
#   ctest --test-dir build                          builds, then the behaviour test (essaim test)
cmake_minimum_required(VERSION 3.16)
project(@NAME@ CXX)
set(CMAKE_CXX_STANDARD 17)
if(NOT CMAKE_BUILD_TYPE)
  set(CMAKE_BUILD_TYPE Release)
endif()

# ARGoS through pkg-config, as argos3-examples finds it: the ARGoS API of the essaim that made
# this project (-DARGOS_PREFIX=... picks another essaim; find_package(ARGoS) works too).
set(ARGOS_PREFIX "@ARGOS_PREFIX@" CACHE PATH "the folder holding lib/pkgconfig/argos3_simulator.pc")
list(APPEND CMAKE_PREFIX_PATH "${ARGOS_PREFIX}")
find_package(PkgConfig REQUIRED)
pkg_check_modules(ARGOS REQUIRED argos3_simulator)
include_directories(${CMAKE_SOURCE_DIR} ${ARGOS_INCLUDE_DIRS})
link_directories(${ARGOS_LIBRARY_DIRS})

add_subdirectory(controllers)
add_subdirectory(loop_functions)

# The behaviour test: the build first (a test of its own), then essaim test on the spec.
enable_testing()
find_package(essaim REQUIRED@HINTS@)
add_test(NAME @NAME@_build COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR})
set_tests_properties(@NAME@_build PROPERTIES FIXTURES_SETUP @NAME@_libraries)
essaim_add_test(NAME @NAME@_behaviour SPEC ${CMAKE_CURRENT_SOURCE_DIR}/@NAME@.test.toml)
set_tests_properties(@NAME@_behaviour PROPERTIES FIXTURES_REQUIRED @NAME@_libraries)
)";

const char* kControllerCMakeLists = R"(add_library(@NAME@ SHARED @NAME@.h @NAME@.cpp)
target_link_libraries(@NAME@ argos3core_simulator argos3plugin_simulator_footbot argos3plugin_simulator_genericrobot)
)";

const char* kLoopCMakeLists =
    R"(add_library(@NAME@_loop_functions SHARED @NAME@_loop_functions.h @NAME@_loop_functions.cpp)
target_link_libraries(@NAME@_loop_functions argos3core_simulator argos3plugin_simulator_entities
                      argos3plugin_simulator_footbot)
)";

const char* kCppCTestFile =
    R"(# Written by `essaim new` so that `ctest` here configures and builds the project into build/,
# then runs its test; CMakeLists.txt declares the same for a build folder. Its essaim is the
# one that made the project.
add_test(@NAME@_configure "cmake" "-S" "." "-B" "build")
set_tests_properties(@NAME@_configure PROPERTIES FIXTURES_SETUP "@NAME@_configured")
add_test(@NAME@_build "cmake" "--build" "build")
set_tests_properties(@NAME@_build PROPERTIES FIXTURES_REQUIRED "@NAME@_configured" FIXTURES_SETUP "@NAME@_libraries")
add_test(@NAME@_behaviour "@ESSAIM@" "test" "@NAME@.test.toml" "--junit" "@NAME@.junit.xml")
set_tests_properties(@NAME@_behaviour PROPERTIES TIMEOUT "300" LABELS "essaim;behaviour"
                     FIXTURES_REQUIRED "@NAME@_libraries")
)";

const char* kCppReadme = R"(# @NAME@

What happens: @ABOUT@ (made by `essaim new @NAME@ --template cpp`). An ARGoS C++ project,
laid out as argos3-examples is: it builds against ARGoS's API as essaim provides it and runs
under essaim (docs/cpp-controllers.md).

| file | what |
|---|---|
| `controllers/@NAME@/@NAME@.h`, `.cpp` | the controller: a `CCI_Controller`, `REGISTER_CONTROLLER(..., "@NAME@_controller")` |
| `loop_functions/@NAME@_loop_functions/` | the loop functions: the metric, `spread.csv` in the run's `files/` |
| `experiments/@NAME@.argos` | the experiment: arena, walls, 10 foot-bots, their devices, the libraries |
| `@NAME@.test.toml` | the behaviour test: seeds, ticks, expectations on `files/spread.csv` |
| `CMakeLists.txt` | the build (ARGoS through pkg-config) and the test under ctest |
| `CTestTestfile.cmake` | `ctest` in this folder: configure, build, test |

Build into `build/` (the `.argos` file names the libraries there, as argos3-examples'
do) and run from this folder; a run writes into `runs/@NAME@-SEED/`:

    cmake -S . -B build && cmake --build build
    essaim run experiments/@NAME@.argos
    ctest --test-dir build --output-on-failure    # builds, then essaim test @NAME@.test.toml
)";

struct CppDevice {
  const char* xml_name;
  bool sensor;
  const char* doc;
};
const CppDevice kCppDevices[] = {
    {"differential_steering", false, "CCI_DifferentialSteeringActuator: SetLinearVelocity(left, right) in cm/s"},
    {"leds", false, "CCI_LEDsActuator: SetAllColors, SetSingleColor (13 LEDs)"},
    {"range_and_bearing", false, "CCI_RangeAndBearingActuator: SetData, ClearData"},
    {"footbot_distance_scanner", false, "CCI_FootBotDistanceScannerActuator"},
    {"footbot_gripper", false, "CCI_FootBotGripperActuator"},
    {"footbot_turret", false, "CCI_FootBotTurretActuator"},
    {"positioning", true, "CCI_PositioningSensor: GetReading().Position (m), .Orientation"},
    {"footbot_proximity", true, "CCI_FootBotProximitySensor: GetReadings(), 24 of {Value, Angle}"},
    {"range_and_bearing", true, "CCI_RangeAndBearingSensor: GetReadings(), {Range (cm), HorizontalBearing, Data}"},
    {"footbot_motor_ground", true, "CCI_FootBotMotorGroundSensor: GetReadings(), 4 of {Value, Offset}"},
};
}  // namespace

std::string CppDeviceDoc(const std::string& xml_name, bool sensor) {
  for (const CppDevice& d : kCppDevices)
    if (xml_name == d.xml_name && sensor == d.sensor) return d.doc;
  return "";  // only the declared devices have a comment
}

namespace {
/// "my-swarm" -> "MySwarm": the name as a C++ class name, after its "C".
std::string ClassName(const std::string& name) {
  std::string out;
  bool upper = true;
  for (char ch : name) {
    if (ch == '-' || ch == '_') {
      upper = true;
      continue;
    }
    out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(ch))) : ch;
    upper = false;
  }
  return out;
}

/// "my-swarm" -> "MY_SWARM": the name in a header guard.
std::string GuardName(const std::string& name) {
  std::string out;
  for (char ch : name) out += ch == '-' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return out;
}

std::string Source(const char* text, const ProjectContext& c, const ProjectTemplate& t) {
  std::string out = FilledProjectText(text, c, t);
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"@CLASS@", ClassName(c.name)},
                                 std::pair<std::string, std::string>{"@GUARD@", GuardName(c.name)}})
    for (size_t at = out.find(from); at != std::string::npos; at = out.find(from, at + to.size()))
      out.replace(at, from.size(), to);
  return out;
}
}  // namespace

std::vector<std::pair<std::string, std::string>> CppProjectFiles(const ProjectContext& c, const ProjectTemplate& t) {
  const std::string& n = c.name;
  const std::string controller = "controllers/" + n + "/", loop = "loop_functions/" + n + "_loop_functions/";
  return {{"CMakeLists.txt", Source(kTopCMakeLists, c, t)},
          {"controllers/CMakeLists.txt", "add_subdirectory(" + n + ")\n"},
          {controller + "CMakeLists.txt", Source(kControllerCMakeLists, c, t)},
          {controller + n + ".h", Source(kCppControllerHeader, c, t)},
          {controller + n + ".cpp", Source(kCppController, c, t)},
          {"loop_functions/CMakeLists.txt", "add_subdirectory(" + n + "_loop_functions)\n"},
          {loop + "CMakeLists.txt", Source(kLoopCMakeLists, c, t)},
          {loop + n + "_loop_functions.h", Source(kCppLoopHeader, c, t)},
          {loop + n + "_loop_functions.cpp", Source(kCppLoop, c, t)},
          {"experiments/" + n + ".argos", ArgosFileText(c, t)},
          {n + ".test.toml", SpecText(c, t)},
          {"CTestTestfile.cmake", Source(kCppCTestFile, c, t)},
          {".gitignore", kProjectGitignore},
          {"README.md", Source(kCppReadme, c, t)}};
}

}  // namespace essaim
