// essaim: a fast, headless swarm-robotics simulator for ARGoS foot-bot experiments.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "app/commands.h"

namespace {
const char* kUsage =
    "essaim " ESSAIM_VERSION " - headless swarm simulator for ARGoS foot-bot experiments\n"
    "\n"
    "usage:\n"
    "  essaim run FILE.argos [options]   run an experiment\n"
    "      --ticks N          run exactly N ticks (overrides the experiment length)\n"
    "      --seed S           random seed (overrides random_seed)\n"
    "      --threads N        threads for sense + control (overrides <system threads>)\n"
    "      --out DIR          output folder (default runs/<name>-<seed>)\n"
    "      --set PATH=VALUE   override an XML attribute, e.g. controllers.ctrl.params.speed=20\n"
    "      --quiet            no progress line, no summary\n"
    "      --strict           the first controller error ends the run (exit 1)\n"
    "      --sandbox          untrusted scripts: no io/os/debug/native code, every instruction counted\n"
    "      --lua-budget N     instructions per call into Lua (default 1e9; 0 = unlimited)\n"
    "      --lua-memory MIB   memory per Lua state (default 256; 0 = unlimited)\n"
    "      --lua-seconds S    wall clock per call into Lua (default 60; 0 = unlimited)\n"
    "      --record[=every=N] also write recording.bin (every tick, or every N ticks)\n"
    "  essaim check FILE.argos [--set ...]   validate, list every error\n"
    "  essaim devices                        list supported sensors and actuators\n"
    "  essaim bench [--quick] [--ticks N]    print robot-steps per second on fixed scenarios\n"
    "  essaim replay RUN_DIR [-o FILE]       write RUN_DIR/replay.html, a self-contained replay page\n"
    "  essaim snapshot RUN_DIR --tick T -o FILE.png [--trail N] [--size PX]\n"
    "                                        draw one recorded tick as a PNG\n"
    "  essaim --version | --help\n"
    "\n"
    "exit codes: 0 ok, 1 run failed, 2 bad input (nothing run), 130/143 interrupted (SIGINT/SIGTERM)\n";
}

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? essaim::kExitBadInput : essaim::kExitOk;
  }
  if (args[0] == "--version") {
    std::printf("essaim %s\n", ESSAIM_VERSION);
    return 0;
  }
  std::string cmd = args[0];
  args.erase(args.begin());
  if (cmd == "run") return essaim::RunCommand(args);
  if (cmd == "check") return essaim::CheckCommand(args);
  if (cmd == "devices") return essaim::DevicesCommand(args);
  if (cmd == "bench") return essaim::BenchCommand(args);
  if (cmd == "replay") return essaim::ReplayCommand(args);
  if (cmd == "snapshot") return essaim::SnapshotCommand(args);
  std::fprintf(stderr, "essaim: unknown command '%s'\n\n%s", cmd.c_str(), kUsage);
  return essaim::kExitBadInput;
}
