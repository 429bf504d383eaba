#include "app/seed_runs.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <map>
#include <thread>

#include "core/paths.h"
#include "core/value_json.h"

extern char** environ;

namespace essaim {

namespace {
namespace fs = std::filesystem;

/// This process's own binary: the children are `essaim run`, whatever PATH holds.
std::string SelfPath() {
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? "essaim" : self.string();
}

std::vector<std::string> RunArguments(const TestSpec& spec, uint64_t seed, const std::string& folder, bool record) {
  std::vector<std::string> args = {SelfPath(),
                                   "run",
                                   fs::absolute(spec.experiment).string(),
                                   "--seed",
                                   std::to_string(seed),
                                   "--out",
                                   folder,
                                   "--quiet",
                                   "--threads",
                                   "1"};  // the seeds are the parallelism
  if (spec.ticks) args.insert(args.end(), {"--ticks", std::to_string(spec.ticks)});
  for (const SpecSetting& s : spec.sets) args.insert(args.end(), {"--set", s.path + "=" + s.value});
  if (record) args.push_back("--record");
  return args;
}

/// Starts one `essaim run` with stdout and stderr into FOLDER/run.log; its pid, or -1.
pid_t Spawn(const std::vector<std::string>& args, const std::string& workdir, const std::string& folder) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  std::string log = folder + "/run.log";
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  posix_spawn_file_actions_addchdir_np(&actions, workdir.c_str());
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = -1;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

Value ReadJson(const std::string& path) {
  std::string text, error;
  Value v;
  if (ReadFile(path, &text) && ParseJsonValue(text, &v, &error)) return v;
  return Value();
}

/// The last non-empty line of the run's log: what a failed run said last.
std::string LastLogLine(const std::string& folder) {
  std::string text;
  if (!ReadFile(folder + "/run.log", &text)) return "";
  while (!text.empty() && text.back() == '\n') text.pop_back();
  size_t start = text.find_last_of('\n');
  return start == std::string::npos ? text : text.substr(start + 1);
}

void Collect(SeedOutcome* run, int status, const std::string& folder) {
  if (WIFEXITED(status)) run->exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status))
    run->failure =
        std::string("killed by signal ") + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  else if (run->exit_code != 0)
    run->failure = "exit " + std::to_string(run->exit_code) + ": " + LastLogLine(folder);
  run->summary = ReadJson(folder + "/summary.json");
  run->metrics = ReadJson(folder + "/metrics.json");
  run->folder = folder;
  if (run->failure.empty() && run->summary.IsNull()) run->failure = "no summary.json written";
}

struct Running {
  size_t index;
  std::chrono::steady_clock::time_point start;
  bool overdue = false;
};

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

/// A run past the spec's timeout is stopped (SIGKILL) and counts as a failed run.
void StopOverdue(const TestSpec& spec, std::map<pid_t, Running>& running) {
  for (auto& [pid, r] : running) {
    if (r.overdue || Seconds(r.start) < spec.timeout_s) continue;
    kill(pid, SIGKILL);
    r.overdue = true;
  }
}

/// Starts run `index`; false (with the run marked failed) when it could not start.
bool Start(const TestSpec& spec, const SeedRunsOptions& o, size_t index, std::vector<SeedOutcome>* runs,
           std::map<pid_t, Running>* running) {
  SeedOutcome& run = (*runs)[index];
  std::string folder = SeedRunFolder(o.out, run.seed);
  std::error_code ec;
  fs::remove_all(folder, ec);  // our own seed-N folder: the run starts from nothing
  fs::create_directories(folder, ec);
  bool record = o.record_golden && run.seed == spec.golden_seed;
  pid_t pid = ec ? -1 : Spawn(RunArguments(spec, run.seed, folder, record), spec.workdir, folder);
  if (pid < 0) {
    run.failure = "could not start essaim run in " + folder + (ec ? ": " + ec.message() : "");
    return false;
  }
  (*running)[pid] = {index, std::chrono::steady_clock::now(), false};
  return true;
}
/// `arg` as a shell reads it back: bare when safe, else in single quotes.
std::string ShellQuoted(const std::string& arg) {
  const bool safe = !arg.empty() && arg.find_first_not_of(
                                        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                        "0123456789_./=:,+-@%") == std::string::npos;
  if (safe) return arg;
  std::string quoted = "'";
  for (char c : arg) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

/// `path` as written from `from`: relative when below it, else absolute (no ../.. to count).
std::string FromFolder(const std::string& path, const fs::path& from) {
  std::error_code ec;
  fs::path rel = fs::relative(fs::absolute(path), from, ec);
  if (ec || rel.empty() || rel.string().rfind("..", 0) == 0) return fs::weakly_canonical(path, ec).string();
  return rel.string();
}
}  // namespace

std::string RerunCommand(const TestSpec& spec, uint64_t seed, const std::string& out) {
  std::error_code ec;
  const fs::path here = fs::current_path(ec), workdir = fs::absolute(spec.workdir);
  const bool same = fs::equivalent(here, workdir, ec);
  std::vector<std::string> args = {"essaim", "run", FromFolder(spec.experiment, workdir), "--seed",
                                   std::to_string(seed)};
  if (spec.ticks) args.insert(args.end(), {"--ticks", std::to_string(spec.ticks)});
  args.insert(args.end(), {"--out", FromFolder(SeedRunFolder(out, seed), workdir)});
  for (const SpecSetting& s : spec.sets) args.insert(args.end(), {"--set", s.path + "=" + s.value});
  std::string line;
  for (size_t i = 0; i < args.size(); ++i) line += (i ? " " : "") + ShellQuoted(args[i]);
  // In a subshell, so that the user's shell stays where it is.
  return same ? line : "(cd " + ShellQuoted(FromFolder(workdir.string(), here)) + " && " + line + ")";
}

std::string SeedRunFolder(const std::string& out, uint64_t seed) {
  return fs::absolute(out).string() + "/seed-" + std::to_string(seed);
}

std::vector<SeedOutcome> RunSeeds(const TestSpec& spec, const SeedRunsOptions& options) {
  std::vector<SeedOutcome> runs(spec.seeds.size());
  for (size_t i = 0; i < runs.size(); ++i) runs[i].seed = spec.seeds[i];
  std::map<pid_t, Running> running;
  size_t next = 0;
  while (next < runs.size() || !running.empty()) {
    while (next < runs.size() && static_cast<int>(running.size()) < options.jobs)
      Start(spec, options, next++, &runs, &running);
    if (running.empty()) continue;
    int status = 0;
    pid_t pid = waitpid(-1, &status, WNOHANG);
    if (pid <= 0) {
      if (pid < 0 && errno != EINTR) break;  // no child left to wait for: cannot happen, never spin
      StopOverdue(spec, running);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      continue;
    }
    auto it = running.find(pid);
    if (it == running.end()) continue;
    SeedOutcome& run = runs[it->second.index];
    run.seconds = Seconds(it->second.start);
    Collect(&run, status, SeedRunFolder(options.out, run.seed));
    if (it->second.overdue)
      run.failure = "stopped after the spec's timeout of " + std::to_string(spec.timeout_s) + " s";
    running.erase(it);
  }
  return runs;
}

}  // namespace essaim
