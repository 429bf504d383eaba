// The options `run` and `check` share, and what both do with them before a World exists.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "lua/host/lua_guard.h"
#include "model/model.h"
#include "model/xml_loader.h"

namespace CLI {
class App;
}

namespace essaim {

constexpr long long kMaxTicks = 1000000000000LL;  // ~3 years at 10 ticks/s
constexpr long long kMaxThreads = 1024;

struct RunArgs {
  std::string file;
  std::string out;
  std::string set_file;
  std::optional<long long> ticks, seed, threads;
  std::string record;  // --record's value: "" or every=N
  LoadOptions load;
  bool quiet = false, strict = false, sandbox = false;
  bool watch = false;              // --watch: run again whenever an input file changes
  bool log_prefix = false;         // --log-prefix: "[t=120 fb7] " before each log line
  std::string log_dir;             // --log-dir: one file per robot
  uint32_t record_every = 0;       // --record: a frame every N ticks (0: no recording)
  long long memory_log_every = 0;  // --memory-log N: memory.csv every N ticks (0: none)
  long long lua_budget = -1, lua_init_budget = -1, lua_memory_mib = -1;  // -1: the experiment's or the default
  double lua_seconds = -1;                                               // wall clock per Lua call; -1: default
};

/// The options run and check share: the file and what overrides its XML.
void AddExperimentOptions(CLI::App* sub, RunArgs* r);
/// --set-file's entries first, so a --set on the command line wins over the file.
bool ApplyOptions(RunArgs* r, std::string* error);
/// The model, its warnings printed (--quiet too); on failure the errors printed and, in
/// `message`, without the last newline.
std::unique_ptr<Model> LoadOrReport(const RunArgs& r, std::string* message = nullptr);
/// The watchdog's limits: the CLI's, else the experiment's, else the defaults (stricter
/// under --sandbox). docs/sandbox.md.
LuaOptions WatchdogOptions(const Model& m, const RunArgs& r);

}  // namespace essaim
