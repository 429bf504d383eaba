// `essaim debug`: essaim run's one run (run_command.h) with a Debug Adapter Protocol session
// (src/debug) in between: the editor talks over stdin/stdout (nothing else is written to
// stdout then) or one TCP connection (--port); the experiment comes from the command line
// or the launch request.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/commands.h"
#include "app/run_command.h"
#include "app/run_session.h"
#include "app/web_pages.h"
#include "debug/dap_channel.h"
#include "debug/debug_front.h"
#include "debug/debug_session.h"
#include "debug/debug_view.h"
#include "serve/view_server.h"

namespace essaim {

namespace {
struct DebugArgs {
  RunArgs run;
  RunOptionValues values;
  int port = 0;
  int serve = -1;  // the live page's port (0: a free one); -1: none
};

void AddServeOption(CLI::App* app, int* serve) {
  app->add_option("--serve", *serve, "also show the run live in a browser on 127.0.0.1:PORT (0: a free port)")
      ->type_name("PORT")
      ->check(CLI::Range(0, 65535));
}

std::string Canonical(const std::string& path) {
  std::error_code ec;
  const std::string c = std::filesystem::weakly_canonical(path, ec).string();
  return ec ? path : c;
}

/// The launch request's run options over the command line's: `args` parsed as essaim
/// run's options, `experiment` and `cwd` applied.
bool ApplyLaunchArguments(const Value& arguments, RunArgs* r, int* serve, std::string* error) {
  const std::string cwd = StringField(arguments, "cwd");
  if (!cwd.empty() && chdir(cwd.c_str()) != 0) {
    *error = "launch: cwd " + cwd + " is not a folder";
    return false;
  }
  if (const Value* args = arguments.Find("args"); args && !args->list.empty()) {
    CLI::App parser("essaim debug's launch arguments", "essaim debug");
    RunOptionValues values;
    AddRunOptions(&parser, r, &values);
    AddServeOption(&parser, serve);
    parser.get_option("FILE.argos")->required(false);
    std::vector<std::string> words;
    for (const Value& a : args->list) words.push_back(a.text);
    std::reverse(words.begin(), words.end());  // CLI11 takes them last first
    try {
      parser.parse(words);
    } catch (const CLI::ParseError& e) {
      *error = std::string("launch args: ") + e.what();
      return false;
    }
    FinishRunOptions(&parser, r, values);
  }
  const std::string experiment = StringField(arguments, "experiment");
  if (!experiment.empty()) r->file = experiment;
  if (r->file.empty()) *error = "no experiment: give one on the command line or as launch's \"experiment\"";
  return !r->file.empty();
}

/// What the session needs of the model: where breakpoints may be, the threads.
bool DescribeLaunch(const RunArgs& args, const Value& arguments, DebugLaunch* out, std::string* error) {
  RunArgs r = args;  // the run applies the options afresh
  if (!ApplyOptions(&r, error)) return false;
  std::unique_ptr<Model> model = LoadOrReport(r, error);
  if (!model) return false;
  out->experiment_dir = Canonical(std::filesystem::path(Canonical(model->file)).parent_path().string());
  for (const ControllerDef& c : model->controllers)
    if (!c.script.empty()) out->scripts.push_back(Canonical(c.script));
  out->lua_loop_functions = !model->loop_functions.script.empty();
  if (out->lua_loop_functions) out->scripts.push_back(Canonical(model->loop_functions.script));
  for (const RobotDef& robot : model->robots) out->robot_ids.push_back(robot.id);
  out->stop_on_entry = BoolField(arguments, "stopOnEntry");
  return true;
}

// The live page in the front (--serve): its pipe is made before the simulation is forked,
// its server started after, so that no simulation has its threads or listening socket; the
// front's relay loop reads the pipe (no thread of ours).
class FrontView {
 public:
  explicit FrontView(int port) : port_(port) {
    if (port_ >= 0 && pipe(pipe_) != 0) port_ = -1;
  }
  bool Publishes() const { return port_ >= 0; }
  /// In the simulation: the pipe's end it writes to.
  int SimulationEnd() {
    close(pipe_[0]);
    return pipe_[1];
  }
  /// The front's part: started once the simulation is forked, the pipe drained as it relays.
  FrontSide Side(int client_out) {
    if (port_ < 0) return {};
    return {[this, client_out] { Start(client_out); }, pipe_[0], [this] { return feed_->Drain(); }};
  }
  /// In the front, every simulation gone.
  void End() {
    if (server_) server_->Stop();
  }

 private:
  /// Listening; the address told on stderr and to the client (whole messages, before the
  /// relay starts).
  void Start(int client_out) {
    if (port_ < 0) return;
    close(pipe_[1]);
    server_ = std::make_unique<ViewServer>(LivePage());
    std::string error, said;
    if (server_->Start("127.0.0.1", port_, "", &error))
      said = "live view: " + server_->Url("127.0.0.1") + "\n";
    else
      said = "essaim debug: --serve: " + error + "\n";
    std::fprintf(stderr, "%s", said.c_str());
    DapChannel(-1, client_out).Output("console", said);  // seq 1: clients do not check events' seq
    feed_ = std::make_unique<ViewFeed>(pipe_[0], server_.get());
  }

  int port_;
  int pipe_[2] = {-1, -1};
  std::unique_ptr<ViewServer> server_;
  std::unique_ptr<ViewFeed> feed_;
};

RunHooks DebugHooks(DebugSession& session, const RunArgs& r) {
  RunHooks hooks;
  const bool to_log_dir = !r.log_dir.empty();
  hooks.options = [&session, to_log_dir](SimOptions* opt) {
    opt->threads = 1;           // a stop inside a hook pauses everything; results are the same at any count
    opt->lua.wall_seconds = 0;  // a call stopped at a breakpoint may wait for the user for hours
    opt->lua.debugger = &session.Debugger();
    auto printed = opt->log_sink;
    opt->log_sink = [&session, printed, to_log_dir](char stream, const std::string& line, const LogOrigin& from) {
      session.LogLine(stream, line);
      if (to_log_dir && printed) printed(stream, line, from);
    };
  };
  hooks.before_tick = [&session](World& world) { return session.BeforeTick(world); };
  hooks.finishing = [&session](RunInfo* info) {
    session.RunFinished();
    info->debug = session.Record();
  };
  hooks.error = [&session](const std::string& message) { session.LogLine('E', message); };
  return hooks;
}

int Debug(DebugArgs& a) {
  signal(SIGPIPE, SIG_IGN);  // a client gone mid-write is read as gone, not a killed process
  std::string error;
  int in = STDIN_FILENO, out = -1;
  if (a.port > 0) {
    in = out = AcceptOneClient(a.port, &error);
    if (in < 0) {
      std::fprintf(stderr, "essaim debug: %s\n", error.c_str());
      return kExitBadInput;
    }
  } else {
    out = dup(STDOUT_FILENO);  // the protocol's alone: anything else printed goes to stderr
    dup2(STDERR_FILENO, STDOUT_FILENO);
  }
  DapChannel channel(in, out);
  RunArgs run = a.run;
  int serve = a.serve;
  DebugSession session(channel, [&](const Value& arguments, DebugLaunch* launch, std::string* message) {
    run = a.run;
    serve = a.serve;
    return ApplyLaunchArguments(arguments, &run, &serve, message) && DescribeLaunch(run, arguments, launch, message);
  });
  // The client left before the run started: after a refused launch, as bad input.
  if (!session.Configure()) return session.LaunchFailed() ? kExitBadInput : kExitOk;
  // From here this process is the front; the run happens in the simulation it forks.
  const pid_t front = getpid();
  FrontLink link;
  FrontView view(serve);
  const int front_code = StartFront(in, out, &link, view.Side(out));
  if (front_code >= 0) {
    view.End();
    return front_code;
  }
  channel.Rebind(link.sim_socket);
  if (view.Publishes()) session.ServeView(view.SimulationEnd());
  session.EnableGoingBack(front, link);
  RunSession run_session;
  const RunHooks hooks = DebugHooks(session, run);
  std::vector<std::string> inputs;
  run.quiet = true;
  const int code = RunExperiment(run_session, run, &inputs, &hooks);
  std::fflush(stdout);
  session.Ended(code);
  session.EndCheckpoints();
  EndSimulation(link, code);  // no destructors: a forked copy has no watchdog thread to join
}
}  // namespace

CommandMain AddDebugCommand(CLI::App& app) {
  auto a = std::make_shared<DebugArgs>();
  CLI::App* sub = app.add_subcommand(
      "debug", "debug the experiment's Lua controllers from an editor: Debug Adapter Protocol on stdin/stdout");
  AddRunOptions(sub, &a->run, &a->values);
  sub->get_option("FILE.argos")->required(false);
  sub->remove_option(sub->get_option("--watch"));  // one run, under the editor's control
  sub->add_option("--port", a->port, "serve one client on 127.0.0.1:N instead of stdin/stdout")
      ->type_name("N")
      ->check(CLI::Range(1, 65535));
  AddServeOption(sub, &a->serve);
  sub->footer("Example (VS Code, nvim-dap: docs/debugging.md):\n  essaim debug arenas/foraging.argos --ticks 600");
  return [a, sub] {
    FinishRunOptions(sub, &a->run, a->values);
    return Debug(*a);
  };
}

}  // namespace essaim
