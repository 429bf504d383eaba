// <framework>: threads, the Lua watchdog, the size and count limits (<system>), and the
// experiment's length, rate and seed (<experiment>), with the command line's overrides.
#include <algorithm>
#include <chrono>
#include <string>
#include <utility>

#include "model/xml_loader_impl.h"

namespace essaim::xml_loader {

// Upper bounds on .argos numbers that size threads or casts (docs/compatibility.md).
constexpr long long kMaxThreads = 1024;
constexpr long long kMaxTicksPerSecond = 1000000;
constexpr double kMaxLengthTicks = 1e15;

void Loader::LoadFramework(const XMLElement* e) {
  CheckChildren(e, {"system", "experiment", "profiling"}, "expected system, experiment, profiling");
  ExperimentDef& x = model_->experiment;
  if (const XMLElement* sys = e->FirstChildElement("system")) {
    // Bounded so a typo cannot ask std::thread for 100000 threads (std::system_error, abort).
    long long threads = Int(sys, "threads", 0);
    if (threads < 0 || threads > kMaxThreads)
      Error(sys, "threads must be between 0 and " + std::to_string(kMaxThreads));
    else
      x.threads = static_cast<int>(threads);
    LoadWatchdog(sys, &x);
    LoadLimits(sys, &x.limits);
    std::string method = Str(sys, "method", "balance_quantity");
    if (method != "balance_quantity" && method != "balance_length")
      Error(sys, "method must be balance_quantity or balance_length");
  }
  const XMLElement* exp = e->FirstChildElement("experiment");
  if (!exp) {
    Error(e, "missing required <experiment>");
    return;
  }
  long long tps = Int(exp, "ticks_per_second", 10, true);
  if (tps <= 0 || tps > kMaxTicksPerSecond) {
    Error(exp, "ticks_per_second must be between 1 and " + std::to_string(kMaxTicksPerSecond));
    tps = 10;
  }
  x.ticks_per_second = static_cast<int>(tps);
  double length = Double(exp, "length", 0);
  // ARGoS truncates length × ticks_per_second. The bound keeps the
  // product inside uint64_t: length="1e300" was undefined behaviour in the cast.
  double ticks = length * x.ticks_per_second;
  if (length < 0) {
    Error(exp, "length must be >= 0");
  } else if (ticks > kMaxLengthTicks) {
    Error(exp, "length is too long: length x ticks_per_second must be at most 1e15 ticks");
  } else {
    x.length_ticks = static_cast<uint64_t>(ticks);
  }
  long long seed = Int(exp, "random_seed", 0);
  if (seed < 0) Error(exp, "random_seed must be >= 0");
  x.seed = static_cast<uint64_t>(std::max(0LL, seed));
  if (x.seed == 0) {
    // ARGoS seeds from the clock when no seed is given; the summary records which.
    x.seed = static_cast<uint64_t>(std::chrono::system_clock::now().time_since_epoch().count() / 1000 % 1000000) + 1;
  }
  if (Has(exp, "real_time") && Bool(exp, "real_time", false))
    Warn(exp, "real_time ignored: essaim runs as fast as it can");
  if (options_.ticks) x.length_ticks = *options_.ticks;
  if (options_.seed) x.seed = *options_.seed;
  if (options_.threads) x.threads = *options_.threads;
}

// The Lua watchdog's limits (0 = unlimited); the CLI's --lua-budget/--lua-init-budget/--lua-memory win.
void Loader::LoadWatchdog(const XMLElement* sys, ExperimentDef* x) {
  if (Has(sys, "lua_budget")) {
    x->lua_budget = Int(sys, "lua_budget", 0);
    if (x->lua_budget < 0) Error(sys, "lua_budget must be >= 0 (instructions per step() call; 0 = unlimited)");
  }
  if (Has(sys, "lua_init_budget")) {
    x->lua_init_budget = Int(sys, "lua_init_budget", 0);
    if (x->lua_init_budget < 0)
      Error(sys, "lua_init_budget must be >= 0 (instructions per init(), reset() or top-level call; 0 = unlimited)");
  }
  if (Has(sys, "lua_memory")) {
    x->lua_memory_mib = Int(sys, "lua_memory", 0);
    if (x->lua_memory_mib < 0 || x->lua_memory_mib > (1LL << 30))
      Error(sys, "lua_memory must be between 0 and 2^30 (MiB per Lua state; 0 = unlimited)");
  }
}

// The size and count limits (docs/safety.md): raised, never lowered below what a normal
// experiment needs, by <system max_...>.
void Loader::LoadLimits(const XMLElement* sys, LimitsDef* limits) {
  for (auto [name, value] : {std::pair<const char*, double*>{"max_arena_size", &limits->arena_size},
                             {"max_entity_size", &limits->entity_size}}) {
    if (!Has(sys, name)) continue;
    const double v = Double(sys, name, *value);
    if (v > 0 && v <= kMaxCoordinate)
      *value = v;
    else
      Error(sys, std::string(name) + " must be in (0, 1e6] m");
  }
  for (auto [name, value] : {std::pair<const char*, long long*>{"max_floor_pixels", &limits->floor_pixels},
                             {"max_entities", &limits->entities}}) {
    if (!Has(sys, name)) continue;
    const long long v = Int(sys, name, *value);
    if (v >= 1)
      *value = v;
    else
      Error(sys, std::string(name) + " must be >= 1");
  }
}

}  // namespace essaim::xml_loader
