// `essaim devices`: the device table, as the loader and the Lua host use it.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>
#include <string>

#include "app/commands.h"
#include "app/lua_annotations.h"
#include "model/device_table.h"

namespace essaim {

namespace {
// What every controller has beside its devices (docs/compatibility.md).
const char* kAlwaysThere =
    "ALWAYS THERE (every controller, nothing to declare in the XML)\n"
    "  robot.id  -> the robot's id, a string (\"fb0\")\n"
    "  robot.params  -> the <params> attributes, all strings (tonumber() them); a key that no script\n"
    "      reads is warned about at the end of the run, with the closest key read (--strict: an error)\n"
    "  robot.random  -> this robot's generator, seeded from the experiment's random_seed:\n"
    "      uniform() in [0,1), uniform(max), uniform(min, max), uniform_int(max), uniform_int(min, max),\n"
    "      gaussian(sd [, mean]), exponential(mean), poisson(mean), bernoulli([p])\n"
    "  log(...), logerr(...)  -> one line on stdout / stderr, the arguments joined with no separator\n"
    "      as ARGoS writes them (numbers %g, booleans 1/0); print(...) separates them with tabs;\n"
    "      print(...) and io.write(...) to io.stdout go the same way (--log-prefix, --log-dir);\n"
    "      io.output(file) sends io.write(...) to that file, as in Lua\n"
    "  vector2, vector3, quaternion  -> ARGoS's math types\n"
    "\n";

int Devices() {
  std::fputs(kAlwaysThere, stdout);
  for (int sensors = 0; sensors < 2; ++sensors) {
    std::printf("%s (inside <%s>)\n", sensors ? "SENSORS" : "ACTUATORS", sensors ? "sensors" : "actuators");
    for (const DeviceRow& row : kDeviceRows) {
      if (row.is_sensor != (sensors == 1)) continue;
      std::printf("  <%s implementation=\"%s\">  -> robot.%s%s\n", row.xml_name, row.implementations, row.lua_key,
                  row.supported ? "" : "   [not supported yet]");
      std::printf("      %s\n", row.doc);
      std::printf("      cost: %s\n", CostName(row.cost));
      for (const DeviceAttr& a : row.attrs)
        std::printf("      %-22s %s%s%s%s\n", a.name, a.doc, a.required ? " (required)" : "",
                    a.default_value[0] ? ", default " : "", a.default_value);
    }
    std::printf("\n");
  }
  return 0;
}
}  // namespace

CommandMain AddDevicesCommand(CLI::App& app) {
  auto format = std::make_shared<std::string>();
  CLI::App* sub =
      app.add_subcommand("devices", "list supported sensors and actuators, their XML attributes and Lua tables");
  CLI::Option* defs = sub->add_flag_callback(
      "--lua-defs", [format] { *format = "lua-defs"; },
      "print the Lua language server annotations of robot.*, log and the loop functions' API");
  sub->add_flag_callback(
         "--luacheck", [format] { *format = "luacheck"; }, "print a .luacheckrc declaring essaim's globals")
      ->excludes(defs);
  sub->footer("Example:\n  essaim devices | less\n  essaim devices --lua-defs > essaim.d.lua");
  return [format] {
    if (format->empty()) return Devices();
    std::fputs((*format == "luacheck" ? LuacheckConfig() : LuaLanguageServerDefs()).c_str(), stdout);
    return 0;
  };
}

}  // namespace essaim
