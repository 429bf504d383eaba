// `essaim devices`: the device table, as the loader and the Lua host use it.
#include <CLI/CLI.hpp>
#include <cstdio>

#include "app/commands.h"
#include "model/device_table.h"

namespace essaim {

namespace {
int Devices() {
  for (int sensors = 0; sensors < 2; ++sensors) {
    std::printf("%s (inside <%s>)\n", sensors ? "SENSORS" : "ACTUATORS", sensors ? "sensors" : "actuators");
    for (const DeviceRow& row : DeviceTable()) {
      if (row.is_sensor != (sensors == 1)) continue;
      std::printf("  <%s implementation=\"%s\">  -> robot.%s%s\n", row.xml_name, row.implementations, row.lua_key,
                  row.supported ? "" : "   [not supported yet]");
      std::printf("      %s\n", row.doc);
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
  app.add_subcommand("devices", "list supported sensors and actuators, their XML attributes and Lua tables")
      ->footer("Example:\n  essaim devices | less");
  return Devices;
}

}  // namespace essaim
