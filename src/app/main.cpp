// essaim: a fast, headless swarm-robotics simulator for ARGoS foot-bot experiments.
// The command line is CLI11 (docs/cli.md); each subcommand is declared in its cmd_*.cpp.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <string>

#include "app/cli_support.h"
#include "app/commands.h"
#include "app/completion.h"

namespace {
const char* kFooter =
    "Run 'essaim help COMMAND' or 'essaim COMMAND --help' for a command's options.\n"
    "Exit codes: 0 ok, 1 run failed, 2 bad input (nothing run), 130/143 interrupted (SIGINT/SIGTERM).";

std::vector<std::string> CommandNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  return names;
}

bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// ARGoS habits: `argos3 -c FILE.argos` became `essaim -c FILE.argos`, or just
// `essaim FILE.argos`. Both run the file as `essaim run FILE.argos` would, with a hint.
std::vector<std::string> ArgosHabit(int argc, char** argv) {
  std::vector<std::string> args(argv, argv + argc);
  if (args.size() < 2) return args;
  std::string hint;
  if ((args[1] == "-c" || args[1] == "--config-file") && args.size() >= 3) {
    hint = args[1] + " " + args[2];
    args.erase(args.begin() + 1);
  } else if (EndsWith(args[1], ".argos")) {
    hint = args[1];
  } else {
    return args;
  }
  args.insert(args.begin() + 1, "run");
  std::fprintf(stderr, "essaim: '%s' runs as 'essaim run %s' (commands: run, check, ...; see essaim --help)\n",
               hint.c_str(), args[2].c_str());
  return args;
}

/// Parses the command line; an exit code when that ends the program (help, version, an error).
std::optional<int> Parse(CLI::App& app, std::vector<std::string> args) {
  try {
    args.erase(args.begin());  // CLI11 takes them without the program name, in reverse
    std::reverse(args.begin(), args.end());
    app.parse(args);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string prog = "essaim";
    for (const CLI::App* sub : app.get_subcommands()) prog += " " + sub->get_name();
    std::string what = e.what();
    // CLI11 says "--seed: 1 required S missing" for an option given without its value.
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&e) && what.find(" missing") != std::string::npos)
      what = what.substr(0, what.find(':')) + " needs a value";
    std::fprintf(stderr, "%s: %s\nsee '%s --help'\n", prog.c_str(), what.c_str(), prog.c_str());
    return essaim::kExitBadInput;
  }
  return std::nullopt;
}

/// `essaim help [COMMAND]`.
int Help(CLI::App& app, const std::vector<std::string>& topic, const std::string& main_help) {
  if (topic.empty() || topic[0].empty()) {
    std::cout << main_help;
    return essaim::kExitOk;
  }
  try {
    std::cout << app.get_subcommand(topic[0])->help("essaim");
    return essaim::kExitOk;
  } catch (const CLI::OptionNotFound&) {
    std::string hint = essaim::ClosestName(topic[0], CommandNames(app));
    std::fprintf(stderr, "essaim help: unknown command '%s'%s\n", topic[0].c_str(),
                 hint.empty() ? "" : (" (did you mean '" + hint + "'?)").c_str());
    return essaim::kExitBadInput;
  }
}
}  // namespace

namespace {
/// No command ran: the main help, the options left over, or the closest command's name.
int NoCommand(CLI::App& app, const std::string& main_help) {
  std::vector<std::string> rest = app.remaining();
  if (rest.empty()) {
    std::cerr << main_help;
    return essaim::kExitBadInput;
  }
  if (rest[0].size() > 1 && rest[0][0] == '-') {
    essaim::ReportLeftovers(app, "essaim");
    return essaim::kExitBadInput;
  }
  std::string hint = essaim::ClosestName(rest[0], CommandNames(app));
  std::fprintf(stderr, "essaim: unknown command '%s'%s\nsee 'essaim --help'\n", rest[0].c_str(),
               hint.empty() ? "" : (" (did you mean '" + hint + "'?)").c_str());
  return essaim::kExitBadInput;
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app("essaim " ESSAIM_VERSION " - headless swarm simulator for ARGoS foot-bot experiments", "essaim");
  app.set_version_flag("--version", "essaim " ESSAIM_VERSION);
  app.footer(kFooter);
  app.allow_extras();            // unknown commands and options are answered below, with suggestions
  app.require_subcommand(0, 1);  // `essaim help run`: "run" is help's topic, not a second command
  std::map<std::string, essaim::CommandMain> commands;
  for (auto add : {essaim::AddRunCommand, essaim::AddCheckCommand, essaim::AddDevicesCommand, essaim::AddBenchCommand,
                   essaim::AddReplayCommand, essaim::AddSnapshotCommand, essaim::AddVideoCommand,
                   essaim::AddServeCommand, essaim::AddTestCommand, essaim::AddNewCommand, essaim::AddDebugCommand}) {
    size_t before = app.get_subcommands([](const CLI::App*) { return true; }).size();
    essaim::CommandMain fn = add(app);
    CLI::App* sub = app.get_subcommands([](const CLI::App*) { return true; })[before];
    sub->set_version_flag("--version", "essaim " ESSAIM_VERSION);
    commands[sub->get_name()] = std::move(fn);
  }
  std::string shell;
  CLI::App* completion = app.add_subcommand("completion", "print a shell completion script");
  completion->add_option("SHELL", shell, "the shell (only bash)")->required()->check(CLI::IsMember({"bash"}));
  completion->footer("Example:\n  source <(essaim completion bash)    # e.g. in ~/.bashrc");
  // A prefix command: what follows `help` is a topic, never parsed as a subcommand.
  CLI::App* help = app.add_subcommand("help", "print the help of essaim or of one command (essaim help run)");
  help->prefix_command();

  const std::string main_help = app.help();  // once a subcommand is parsed, help() describes it
  if (std::optional<int> code = Parse(app, ArgosHabit(argc, argv))) return *code;
  if (completion->parsed()) {
    std::cout << essaim::BashCompletion(app);
    return essaim::kExitOk;
  }
  if (help->parsed()) return Help(app, help->remaining(), main_help);
  for (const CLI::App* sub : app.get_subcommands()) {
    if (essaim::ReportLeftovers(*sub, "essaim " + sub->get_name())) return essaim::kExitBadInput;
    return commands.at(sub->get_name())();
  }
  return NoCommand(app, main_help);
}
