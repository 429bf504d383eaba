// `essaim serve FILE.argos`: the experiment live in a browser, reloaded on save
// (docs/live.md). The server itself is src/serve/.
#include <CLI/CLI.hpp>
#include <atomic>
#include <cstdio>
#include <memory>
#include <optional>

#include "app/cli_support.h"
#include "app/commands.h"
#include "app/set_file.h"
#include "app/signals.h"
#include "app/web_pages.h"
#include "core/paths.h"
#include "lua/host/watchdog.h"
#include "serve/live_server.h"

namespace essaim {

namespace {

struct ServeArgs {
  ServeOptions serve;
  std::string set_file;
  std::optional<long long> seed;
};

bool IsLoopback(const std::string& host) { return host == "127.0.0.1" || host == "localhost" || host == "::1"; }

int Serve(ServeArgs& a) {
  std::string error;
  // A file with errors is served (the page shows them until it is fixed); no file at all is
  // a mistyped command.
  if (!FileExists(a.serve.file)) {
    std::fprintf(stderr, "essaim serve: %s: no such file\n", a.serve.file.c_str());
    return kExitBadInput;
  }
  if (a.seed) a.serve.load.seed = static_cast<uint64_t>(*a.seed);
  if (!a.set_file.empty()) {
    std::vector<std::string> from_file;
    if (!ReadOverridesFile(a.set_file, &from_file, &error)) {
      std::fprintf(stderr, "essaim serve: %s\n", error.c_str());
      return kExitBadInput;
    }
    a.serve.load.overrides.insert(a.serve.load.overrides.begin(), from_file.begin(), from_file.end());
  }
  if (!IsLoopback(a.serve.host))
    std::fprintf(stderr,
                 "essaim serve: warning: listening on %s: anyone who can reach this machine and has the token "
                 "can drive the simulator and read its scripts' state\n",
                 a.serve.host.c_str());
  a.serve.page = LivePage();
  Watchdog watchdog(ExitStuck);
  SignalCatcher signals(&watchdog);  // a controller stuck in a long step lets go
  a.serve.watchdog = &watchdog;
  a.serve.report = [](const std::string& line) { std::fprintf(stderr, "essaim serve: %s\n", line.c_str()); };
  LiveServer server(a.serve);
  if (!server.Start(&error)) {
    std::fprintf(stderr, "essaim serve: %s\n", error.c_str());
    return kExitBadInput;
  }
  std::printf("%s\n", server.Url().c_str());
  std::fflush(stdout);
  signals.Listen();
  server.Run(signals.CaughtFlag());
  return kExitOk;
}
}  // namespace

CommandMain AddServeCommand(CLI::App& app) {
  auto a = std::make_shared<ServeArgs>();
  CLI::App* sub = app.add_subcommand("serve", "watch an experiment live in a browser; reloads when its files change");
  sub->add_option("FILE.argos", a->serve.file, "the ARGoS experiment file")->required();
  sub->add_option("--port", a->serve.port, "TCP port (default 8765; 0 picks a free one)")
      ->type_name("N")
      ->check(CLI::Range(0, 65535));
  sub->add_option("--host", a->serve.host, "address to listen on (default 127.0.0.1; any other is warned about)")
      ->type_name("H");
  sub->add_option("--token", a->serve.token, "the access token (default: a fresh random one each start)")
      ->type_name("T")
      ->check(CLI::Validator(
          [](std::string& v) {
            return v.size() >= 8 ? std::string() : std::string("a token needs 8 characters or more");
          },
          ""));
  sub->add_option("--seed", a->seed, "random seed, >= 0 (overrides random_seed)")
      ->type_name("S")
      ->check(IntegerIn(0, std::numeric_limits<long long>::max()));
  sub->add_option("--set", a->serve.load.overrides, "override an XML attribute (repeatable)")
      ->type_name("PATH=VALUE")
      ->allow_extra_args(false);
  sub->add_option("--set-file", a->set_file, "a JSON object {\"PATH\": value, ...} of overrides")
      ->type_name("FILE.json");
  sub->footer(
      "Example:\n  essaim serve arenas/foraging.argos     # then open the printed http://127.0.0.1:8765/?token=... "
      "line; Ctrl-C ends");
  return [a] { return Serve(*a); };
}

}  // namespace essaim
