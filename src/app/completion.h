// `essaim completion bash`: a bash completion script made from the CLI11 definitions, so it
// never lists an option the command line does not have.
#pragma once
#include <string>

namespace CLI {
class App;
}

namespace essaim {

/// Completes commands, each command's options, `help COMMAND`, and file names elsewhere.
std::string BashCompletion(const CLI::App& app);

}  // namespace essaim
