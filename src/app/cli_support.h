// Helpers shared by the subcommands' CLI11 definitions: integer checks with messages that say
// what is allowed, and "did you mean" answers for what CLI11 leaves unrecognised.
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "core/strings.h"  // ClosestName

namespace essaim {

/// Accepts a whole number in [min, max]; the message names the bounds and `why` (e.g.
/// "0 would run forever"), so `--threads 0` and `--threads 100000` each get a true answer.
CLI::Validator IntegerIn(long long min, long long max, const std::string& why = "");

/// After parsing: prints the first unrecognised argument of `sub` (an unknown option with a
/// suggestion, or an extra positional) and returns true when there was one.
bool ReportLeftovers(const CLI::App& sub, const std::string& prog);

/// Every long and short option name of `app` ("--ticks", "-o"), for suggestions and completion.
std::vector<std::string> OptionNames(const CLI::App& app);

}  // namespace essaim
