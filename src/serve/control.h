// The commands a page or a script sends to POST /api/control, checked before they reach
// the simulation: {"cmd": "play"|"pause"|"step"|"run"|"speed"|"reset", ...}.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace essaim {

enum class ControlKind { Play, Pause, Step, Speed, Reset };

struct ControlCommand {
  ControlKind kind = ControlKind::Pause;
  uint64_t ticks = 1;            // step / run: how many ticks, then paused
  double speed = 1;              // speed: multiple of real time, 0 = as fast as it goes
  std::optional<uint64_t> seed;  // reset: this seed from now on
  bool new_seed = false;         // reset: a random seed
};

/// False with `error` for a body that is not a JSON object with a known "cmd" and valid
/// arguments: {"cmd": "step", "ticks": N} (N from 1 to 10^9; "run" is the same),
/// {"cmd": "speed", "value": X} (0 or 0.01 to 10000), {"cmd": "reset", "seed": S} or
/// {"cmd": "reset", "new_seed": true}.
bool ParseControl(const std::string& body, ControlCommand* out, std::string* error);
/// A non-negative integer from a query parameter; nullopt when it is not one.
std::optional<long long> ParseIndex(const std::string& text);

}  // namespace essaim
