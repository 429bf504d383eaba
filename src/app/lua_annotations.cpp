#include "app/lua_annotations.h"

#include <array>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "model/device_table.h"

namespace essaim {

namespace {
struct DeviceAnnotation {
  DeviceType type;
  const char* class_name;  // the LuaLS class of what the row puts into robot.<lua_key>
  const char* fields;      // its ---@field lines ("---@field [integer] T": an array of readings)
};

// One per DeviceType, in enum order (checked below). Reading classes are in kReadingClasses.
constexpr std::array<DeviceAnnotation, kDeviceCount> kAnnotations = {{
    {DeviceType::WheelsActuator, "essaim.WheelsActuator",
     "---@field set_velocity fun(left: number, right: number) wheel speeds in cm/s\n"},
    {DeviceType::LedsActuator, "essaim.LedsActuator",
     "---@field set_all_colors fun(color: string|number, green?: number, blue?: number) a name, \"r,g,b,a\" or r, g, "
     "b\n"
     "---@field set_single_color fun(index: integer, color: string|number, green?: number, blue?: number) LED 1..13\n"},
    {DeviceType::RabActuator, "essaim.RabActuator",
     "---@field set_data fun(data: integer[]|integer, value?: integer) the whole payload, or byte i (1-based) = value\n"
     "---@field clear_data fun() every byte 0\n"},
    {DeviceType::ScannerActuator, "essaim.ScannerActuator",
     "---@field enable fun()\n---@field disable fun()\n"
     "---@field set_angle fun(angle: number) rad, fixed direction\n---@field set_rpm fun(rpm: number) rotating\n"},
    {DeviceType::GripperActuator, "essaim.GripperActuator",
     "---@field lock_positive fun()\n---@field lock_negative fun()\n---@field unlock fun()\n"},
    {DeviceType::TurretActuator, "essaim.TurretActuator",
     "---@field set_rotation fun(angle: number) rad (position control)\n"
     "---@field set_rotation_speed fun(speed: number) speed control\n"
     "---@field set_position_control_mode fun()\n---@field set_speed_control_mode fun()\n"
     "---@field set_passive_mode fun()\n"},
    {DeviceType::WheelsSensor, "essaim.WheelsSensor",
     "---@field velocity_left number cm/s\n---@field velocity_right number cm/s\n"
     "---@field distance_left number cm since the last tick\n---@field distance_right number cm since the last tick\n"
     "---@field axis_length number cm\n"},
    {DeviceType::PositioningSensor, "essaim.PositioningSensor",
     "---@field position essaim.vector3 m\n---@field orientation essaim.quaternion\n"},
    {DeviceType::ProximitySensor, "essaim.ProximitySensor", "---@field [integer] essaim.ValueAngle 1..24\n"},
    {DeviceType::LightSensor, "essaim.LightSensor", "---@field [integer] essaim.ValueAngle 1..24\n"},
    {DeviceType::BaseGroundSensor, "essaim.BaseGroundSensor", "---@field [integer] essaim.GroundReading 1..8\n"},
    {DeviceType::MotorGroundSensor, "essaim.MotorGroundSensor", "---@field [integer] essaim.GroundReading 1..4\n"},
    {DeviceType::RabSensor, "essaim.RabSensor", "---@field [integer] essaim.RabReading one per message received\n"},
    {DeviceType::ScannerSensor, "essaim.ScannerSensor",
     "---@field short_range essaim.AngleDistance[]\n---@field long_range essaim.AngleDistance[]\n"},
    {DeviceType::CameraSensor, "essaim.CameraSensor",
     "---@field [integer] essaim.Blob one per LED seen\n---@field enable fun()\n---@field disable fun()\n"},
    {DeviceType::BatterySensor, "essaim.BatterySensor",
     "---@field available_charge number 0..1\n---@field time_left number s\n"},
    {DeviceType::TurretEncoderSensor, "essaim.TurretEncoderSensor", "---@field rotation number rad\n"},
}};

constexpr bool AnnotationsComplete() {
  for (int i = 0; i < kDeviceCount; ++i)
    if (static_cast<int>(kAnnotations[i].type) != i || !kAnnotations[i].class_name || !kAnnotations[i].fields)
      return false;
  return true;
}
static_assert(AnnotationsComplete(), "kAnnotations: one annotation per DeviceType, in enum order");

const char* kReadingClasses =
    "---@class essaim.ValueAngle\n---@field value number\n---@field angle number rad\n\n"
    "---@class essaim.GroundReading\n---@field value number\n---@field offset essaim.vector2 m\n\n"
    "---@class essaim.RabReading\n---@field range number cm\n---@field horizontal_bearing number rad\n"
    "---@field vertical_bearing number rad\n---@field data integer[]\n\n"
    "---@class essaim.AngleDistance\n---@field angle number rad\n---@field distance number cm (-1, -2: none)\n\n"
    "---@class essaim.Blob\n---@field distance number cm\n---@field angle number rad\n"
    "---@field color {red: integer, green: integer, blue: integer}\n\n";

// What every controller has beside its devices (`essaim devices`, docs/compatibility.md).
const char* kAlwaysThere =
    "---@class essaim.vector2\n---@field x number\n---@field y number\n\n"
    "---@class essaim.vector3\n---@field x number\n---@field y number\n---@field z number\n\n"
    "---@class essaim.quaternion\n---@field toeulerangles fun(self: essaim.quaternion): number, number, number\n"
    "---@field toangleaxis fun(self: essaim.quaternion): number, essaim.vector3\n"
    "---@field inverse fun(self: essaim.quaternion): essaim.quaternion\n"
    "---@field normalize fun(self: essaim.quaternion): essaim.quaternion\n\n"
    "---@class essaim.Random\n---@field uniform fun(a?: number, b?: number): number [0,1), [0,a) or [a,b)\n"
    "---@field uniform_int fun(a: integer, b?: integer): integer\n"
    "---@field gaussian fun(sd: number, mean?: number): number\n---@field exponential fun(mean: number): number\n"
    "---@field poisson fun(mean: number): integer\n---@field bernoulli fun(p?: number): boolean\n\n";

const char* kGlobals =
    "---@type essaim.Robot\nrobot = {}\n\n"
    "---One line on stdout, the arguments joined with no separator as ARGoS writes them.\n---@param ... any\n"
    "function log(...) end\n\n"
    "---One line on stderr, the arguments joined with no separator as ARGoS writes them.\n---@param ... any\n"
    "function logerr(...) end\n\n"
    "---@param x? number\n---@param y? number\n---@return essaim.vector2\nfunction vector2(x, y) end\n\n"
    "---@param x? number\n---@param y? number\n---@param z? number\n---@return essaim.vector3\n"
    "function vector3(x, y, z) end\n\n"
    "---@param ... number|essaim.vector3\n---@return essaim.quaternion\nfunction quaternion(...) end\n\n";

// The loop functions' API (docs/loop-functions.md).
const char* kLoopFunctions =
    "---@class essaim.Entity\n---@field id string\n---@field kind string \"foot-bot\", \"box\", \"cylinder\", "
    "\"light\"\n"
    "---@field position fun(self: essaim.Entity): number, number, number\n"
    "---@field heading fun(self: essaim.Entity): number\n"
    "---@field set_pose fun(self: essaim.Entity, x: number, y: number, yaw?: number)\n"
    "---@field movable fun(self: essaim.Entity): boolean\n---@field led_count fun(self: essaim.Entity): integer\n"
    "---@field led_color fun(self: essaim.Entity, i: integer): integer, integer, integer\n"
    "---@field set_led_color fun(self: essaim.Entity, ...)\n---@field intensity fun(self: essaim.Entity): number\n"
    "---@field set_intensity fun(self: essaim.Entity, v: number)\n"
    "---@field color fun(self: essaim.Entity): integer, integer, integer\n"
    "---@field set_color fun(self: essaim.Entity, c: string|integer[])\n\n"
    "---@class essaim.RobotHandle: essaim.Entity\n---@field index integer\n"
    "---@field battery fun(self: essaim.RobotHandle): number\n"
    "---@field set_battery fun(self: essaim.RobotHandle, charge: number)\n"
    "---@field alive fun(self: essaim.RobotHandle): boolean\n---@field kill fun(self: essaim.RobotHandle)\n"
    "---@field led fun(self: essaim.RobotHandle, i: integer): integer, integer, integer\n"
    "---@field controller_ok fun(self: essaim.RobotHandle): boolean\n"
    "---@field lua_global fun(self: essaim.RobotHandle, name: string): any\n"
    "---@field set_lua_global fun(self: essaim.RobotHandle, name: string, value: any)\n\n"
    "---@class essaim.Experiment\n---@field tick integer\n---@field ticks_per_second integer\n"
    "---@field length_ticks integer 0: unlimited\n---@field seed integer\n"
    "---@field params table<string, string|table<string, string>>\n"
    "---@field arena {size_x: number, size_y: number, center_x: number, center_y: number}\n"
    "---@field robots essaim.RobotHandle[]\n---@field random essaim.Random\n---@field output_dir string\n"
    "---@field timeseries fun(row: table[]) one row: an array of {name, value} pairs\n"
    "---@field entities fun(kind?: string): essaim.Entity[]\n"
    "---@field add_entity fun(kind: string, spec: table): essaim.Entity\n"
    "---@field remove_entity fun(h: essaim.Entity)\n\n"
    "---@type essaim.Experiment\nexperiment = {}\n";

/// robot.<key>'s rows: a key the sensor and the actuator share (wheels) gets both classes.
std::map<std::string, std::vector<const DeviceRow*>> RowsByKey() {
  std::map<std::string, std::vector<const DeviceRow*>> keys;
  for (const DeviceRow& row : kDeviceRows) keys[row.lua_key].push_back(&row);
  return keys;
}

std::string RobotClass() {
  std::ostringstream defs, robot;
  robot << "---@class essaim.Robot\n---@field id string the robot's id (\"fb0\")\n"
        << "---@field params table<string, string> the <params> attributes, all strings\n"
        << "---@field random essaim.Random this robot's generator\n";
  for (const auto& [key, rows] : RowsByKey()) {
    defs << "---@class essaim.robot." << key << ":";
    for (size_t i = 0; i < rows.size(); ++i) defs << (i ? ", " : " ") << kAnnotations[int(rows[i]->type)].class_name;
    defs << "\n\n";
    robot << "---@field " << key << " essaim.robot." << key << " <" << rows[0]->xml_name << ">: " << rows[0]->doc
          << "\n";
  }
  return defs.str() + robot.str() + "\n";
}

/// The field names of one ---@field block; true in `indexed` when it has [integer] readings.
std::vector<std::string> FieldNames(const std::string& block, bool* indexed) {
  std::vector<std::string> names;
  std::istringstream in(block);
  std::string tag, name, rest;
  while (in >> tag >> name && std::getline(in, rest)) {
    if (name == "[integer]") *indexed = true;
    if (name != "[integer]") names.push_back(name);
  }
  return names;
}

/// experiment.* as the LuaLS class declares it: one list of fields for both files.
std::string LuacheckExperimentFields() {
  std::string text = kLoopFunctions;
  size_t start = text.find("---@class essaim.Experiment\n");
  size_t end = text.find("\n\n", start);
  bool indexed = false;
  std::string out;
  for (const std::string& n : FieldNames(text.substr(start, end - start), &indexed))
    if (n != "essaim.Experiment") out += n + " = {other_fields = true}, ";
  return out;
}

std::string LuacheckRobotFields() {
  std::string out =
      "      id = {}, params = {other_fields = true},\n"
      "      random = {fields = {\"uniform\", \"uniform_int\", \"gaussian\", \"exponential\", "
      "\"poisson\", \"bernoulli\"}},\n";
  for (const auto& [key, rows] : RowsByKey()) {
    bool indexed = false;
    std::set<std::string> names;
    for (const DeviceRow* row : rows)
      for (const std::string& n : FieldNames(kAnnotations[int(row->type)].fields, &indexed)) names.insert(n);
    out += "      " + key + " = {" + (indexed ? "other_fields = true, " : "") + "fields = {";
    for (const std::string& n : names) out += n + " = {other_fields = true}, ";
    out += "}},\n";
  }
  return out;
}
}  // namespace

std::string LuaLanguageServerDefs() {
  std::string out =
      "---@meta\n"
      "-- essaim's Lua API for the Lua language server, made by `essaim devices --lua-defs` from the device\n"
      "-- table of essaim " ESSAIM_VERSION
      ": regenerate it after an upgrade rather than editing it.\n"
      "-- luacheck: ignore\n"
      "-- (declarations, not a script: `luacheck .` in a project holding this file skips it)\n\n";
  out += kAlwaysThere;
  out += kReadingClasses;
  for (const DeviceAnnotation& a : kAnnotations)
    out += std::string("---@class ") + a.class_name + "\n" + a.fields + "\n";
  return out + RobotClass() + kGlobals + kLoopFunctions;
}

std::string LuacheckConfig() {
  return "-- luacheck configuration for essaim scripts, made by `essaim devices --luacheck` from the device\n"
         "-- table of essaim " ESSAIM_VERSION
         ": regenerate it after an upgrade rather than editing it.\n"
         "std = \"lua54\"\n"
         "-- A controller's and a loop function's hooks and state are globals the host calls or copies.\n"
         "allow_defined_top = true\n"
         "ignore = {\"131\"}  -- such a global is read by the host (a hook) or another script (r:lua_global)\n"
         "globals = {\"init\", \"step\", \"reset\", \"destroy\", \"pre_step\", \"post_step\", "
         "\"is_experiment_finished\", \"post_experiment\", \"floor_color\"}\n"
         "read_globals = {\n  \"log\", \"logerr\", \"vector2\", \"vector3\", \"quaternion\",\n"
         "  robot = {\n    fields = {\n" +
         LuacheckRobotFields() +
         "    },\n  },\n"
         "  experiment = {fields = {" +
         LuacheckExperimentFields() +
         "}},\n"
         "}\n";
}

}  // namespace essaim
