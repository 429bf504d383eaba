// `essaim test SPEC.toml`: an experiment over a set of seeds, its expectations checked over the
// runs (docs/testing.md). Exit 0 when every expectation holds, 1 when one does not, 2 for a
// mistake of the spec: one that cannot be read (nothing run), or a value no run produced.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>
#include <thread>

#include "app/cli_support.h"
#include "app/commands.h"
#include "app/expectation.h"
#include "app/golden_run.h"
#include "app/seed_runs.h"
#include "app/spec_checks.h"
#include "app/test_report.h"
#include "app/test_spec.h"
#include "core/paths.h"

namespace essaim {

namespace {
struct TestArgs {
  std::string spec;
  int jobs = 0;  // 0: one per core
  std::string junit;
  std::string out;
  bool update = false;
};

/// The built-in first row: every run ended with exit 0 and wrote its summary.
ReportRow FinishedRow(const std::vector<SeedOutcome>& runs, const std::string& out) {
  ReportRow row;
  row.expectation = "every run finishes (exit 0)";
  for (const SeedOutcome& run : runs) {
    if (run.failure.empty()) continue;
    row.failed_seeds.push_back(run.seed);
    row.details.push_back("seed " + std::to_string(run.seed) + ": " + run.failure +
                          " (log: " + SeedRunFolder(out, run.seed) + "/run.log)");
  }
  row.pass = row.failed_seeds.empty();
  row.value = std::to_string(runs.size() - row.failed_seeds.size()) + "/" + std::to_string(runs.size()) + " runs";
  return row;
}

ReportRow GoldenRow(const TestSpec& spec, const std::vector<SeedOutcome>& runs, const TestArgs& args) {
  ReportRow row;
  row.expectation = "golden " + spec.golden + " (seed " + std::to_string(spec.golden_seed) + ")";
  for (const SeedOutcome& run : runs) {
    if (run.seed != spec.golden_seed) continue;
    GoldenResult g = CheckGolden(spec.golden, run, SeedRunFolder(args.out, run.seed), args.update);
    row.pass = g.pass;
    row.value = g.value;
    row.details = g.diffs;
    if (!g.pass) row.failed_seeds.push_back(run.seed);
  }
  return row;
}

/// A run's first error, on one line (the traceback is in the run's summary.json and log).
std::string FirstError(const SeedOutcome& run) {
  const Value* errors = run.summary.Find("controller_errors");
  const Value* first = errors && !errors->list.empty() ? errors->list.front().Find("message") : nullptr;
  if (!first) first = run.summary.Find("failure");
  return first ? first->text.substr(0, first->text.find('\n')) : "";
}

/// Under a failed expectation on `errors`: the runs' first errors, the same one said once.
std::vector<std::string> ErrorDetails(const Verdict& v, const std::vector<SeedOutcome>& runs) {
  std::vector<std::pair<std::string, std::string>> seeds_by_error;  // in order of first seen
  for (const SeedOutcome& run : runs) {
    std::string error = FirstError(run);
    if (error.empty() || std::find(v.failed_seeds.begin(), v.failed_seeds.end(), run.seed) == v.failed_seeds.end())
      continue;
    auto it =
        std::find_if(seeds_by_error.begin(), seeds_by_error.end(), [&](const auto& p) { return p.first == error; });
    if (it == seeds_by_error.end()) it = seeds_by_error.insert(seeds_by_error.end(), {error, ""});
    it->second += (it->second.empty() ? "" : ", ") + std::to_string(run.seed);
  }
  std::vector<std::string> details;
  for (size_t i = 0; i < seeds_by_error.size() && i < 3; ++i)
    details.push_back("seed(s) " + seeds_by_error[i].second + ": " + seeds_by_error[i].first);
  return details;
}

TestReport Check(const TestSpec& spec, const std::vector<Expectation>& expectations,
                 const std::vector<SeedOutcome>& runs, const TestArgs& args) {
  TestReport report;
  report.suite = spec.name;
  report.spec_file = spec.file;
  report.rows.push_back(FinishedRow(runs, args.out));
  std::vector<SeedOutcome> summarised;  // a run that failed but wrote its summary still counts
  for (const SeedOutcome& run : runs)
    if (!run.summary.IsNull()) summarised.push_back(run);
  for (const Expectation& e : expectations) {
    std::string mistake = UnknownValueInSpec(spec, e, runs);
    if (!mistake.empty()) {  // a name no run produced: a typo of the spec, not a behaviour
      report.rows.push_back({e.text, "no run has it", false, {}, {mistake}, true});
      continue;
    }
    Verdict v = Evaluate(e, summarised);
    std::vector<std::string> details =
        !v.pass && e.value == "errors" ? ErrorDetails(v, summarised) : std::vector<std::string>{};
    for (size_t i = 0; i < v.notes.size() && i < 3; ++i)  // a file or column missing: say where it was asked
      details.push_back(spec.file + ":" + std::to_string(e.line) + ": " + v.notes[i]);
    report.rows.push_back({e.text, v.value, v.pass, v.failed_seeds, details});
  }
  if (!spec.golden.empty()) report.rows.push_back(GoldenRow(spec, runs, args));
  std::set<uint64_t> shown;  // how to look at one failed run alone, said once per seed
  for (ReportRow& row : report.rows)
    if (!row.pass && !row.failed_seeds.empty() && shown.insert(row.failed_seeds.front()).second)
      row.details.push_back("rerun seed " + std::to_string(row.failed_seeds.front()) +
                            " alone: " + RerunCommand(spec, row.failed_seeds.front(), args.out));
  return report;
}

bool WriteJUnit(const std::string& path, const TestReport& report) {
  std::ofstream out(path, std::ios::trunc);
  out << JUnitXml(report);
  return static_cast<bool>(out.flush());
}

/// Every mistake of the spec on stderr (and as a failed testcase in --junit); exit 2.
int SpecErrors(const TestSpec& spec, const std::vector<std::string>& errors, const TestArgs& args) {
  for (const std::string& e : errors) std::fprintf(stderr, "%s\n", e.c_str());
  std::fprintf(stderr, "essaim test: %zu error(s) in %s; nothing was run\n", errors.size(), args.spec.c_str());
  if (!args.junit.empty() && !WriteJUnit(args.junit, SpecErrorReport(args.spec, spec.name, errors)))
    std::fprintf(stderr, "essaim test: cannot write --junit %s\n", args.junit.c_str());
  return kExitBadInput;
}

int Test(TestArgs& args) {
  TestSpec spec;
  std::vector<std::string> errors;
  std::vector<Expectation> expectations;
  LoadTestSpec(args.spec, &spec, &errors);
  CheckSpec(spec, &expectations, &errors);
  if (!errors.empty()) return SpecErrors(spec, errors, args);
  if (args.out.empty()) args.out = "essaim-test/" + spec.name;
  int jobs = args.jobs ? args.jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  std::printf("essaim test %s: %zu seed(s), %s ticks, %d at a time; runs in %s/\n", spec.file.c_str(),
              spec.seeds.size(), spec.ticks ? std::to_string(spec.ticks).c_str() : "the file's", jobs,
              args.out.c_str());
  std::fflush(stdout);
  auto start = std::chrono::steady_clock::now();
  std::vector<SeedOutcome> runs = RunSeeds(spec, {args.out, jobs, !spec.golden.empty()});
  TestReport report = Check(spec, expectations, runs, args);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << FormatReport(report) << std::flush;
  bool mistakes = false;
  for (const ReportRow& row : report.rows)  // also where a spec's errors always go
    if (row.spec_error) mistakes = true, std::fprintf(stderr, "%s\n", row.details.front().c_str());
  if (!args.junit.empty() && !WriteJUnit(args.junit, report)) {
    std::fprintf(stderr, "essaim test: cannot write --junit %s\n", args.junit.c_str());
    return kExitRunFailed;
  }
  return mistakes ? kExitBadInput : report.Passed() ? kExitOk : kExitRunFailed;
}
}  // namespace

CommandMain AddTestCommand(CLI::App& app) {
  auto args = std::make_shared<TestArgs>();
  CLI::App* sub = app.add_subcommand("test", "run an experiment over seeds and check its expectations (a TOML spec)");
  sub->add_option("SPEC", args->spec, "the test spec (.toml; docs/testing.md)")->required();
  sub->add_option("-j,--jobs", args->jobs, "runs at a time (default: one per core)")->check(IntegerIn(1, 1024));
  sub->add_option("--junit", args->junit, "also write the results as JUnit XML into this file");
  sub->add_option("--out", args->out, "the runs' folders go under it (default essaim-test/SPEC_NAME)");
  sub->add_flag("--update", args->update, "rewrite the spec's golden file from this run, saying what changed");
  sub->footer("Example:\n  essaim test arenas/foraging.test.toml -j 2");
  return [args] { return Test(*args); };
}

}  // namespace essaim
