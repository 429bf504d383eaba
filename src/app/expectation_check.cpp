// Checking an expectation over the runs: reading each run's value, the aggregate, the verdict.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "app/expectation.h"
#include "app/file_column.h"
#include "app/value_names.h"
#include "core/strings.h"

namespace essaim {

namespace {
std::optional<double> NumberOf(const Value* v) {
  if (!v) return std::nullopt;
  switch (v->kind) {
    case Value::Kind::Bool:
      return v->boolean ? 1.0 : 0.0;
    case Value::Kind::Integer:
      return static_cast<double>(v->integer);
    case Value::Kind::Unsigned:
      return static_cast<double>(v->big_unsigned);
    case Value::Kind::Number:
      return v->number;
    default:
      return std::nullopt;
  }
}

/// `a.b.c` inside `root`'s nested maps.
const Value* Lookup(const Value& root, const std::string& dotted) {
  const Value* v = &root;
  for (const std::string& key : Split(dotted, '.')) {
    v = v->Find(key);
    if (!v) return nullptr;
  }
  return v;
}

/// Controller errors, plus one when the run itself failed (a loop-function error, os.exit...).
std::optional<double> ErrorCount(const SeedOutcome& run) {
  const Value* errors = run.summary.Find("controller_errors");
  const Value* status = run.summary.Find("status");
  if (!errors || !status) return std::nullopt;
  return static_cast<double>(errors->list.size()) + (status->text == "failed" ? 1 : 0);
}

/// 6 significant digits: what a table needs (the runs' own files hold the full values).
std::string Short(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

/// Linear interpolation between closest ranks (numpy's default), on sorted values.
double QuantileOf(const std::vector<double>& sorted, double q) {
  double pos = q * static_cast<double>(sorted.size() - 1);
  size_t lo = static_cast<size_t>(std::floor(pos));
  size_t hi = std::min(lo + 1, sorted.size() - 1);
  return sorted[lo] + (sorted[hi] - sorted[lo]) * (pos - static_cast<double>(lo));
}

double AggregateOf(const Expectation& e, std::vector<double> values) {
  std::sort(values.begin(), values.end());
  switch (e.aggregate) {
    case Aggregate::Mean:
      return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
    case Aggregate::Median:
      return QuantileOf(values, 0.5);
    case Aggregate::Min:
      return values.front();
    case Aggregate::Max:
      return values.back();
    default:
      return QuantileOf(values, e.quantile);
  }
}

/// Each: every run holds the comparison; Fraction: the share of runs meeting the inner one.
Verdict CountRuns(const Expectation& e, const std::vector<double>& values, const std::vector<uint64_t>& seeds,
                  std::vector<uint64_t> failed) {
  const Comparison& per_run = e.aggregate == Aggregate::Fraction ? e.per_run : e.check;
  size_t total = values.size() + failed.size(), met = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    if (per_run.Holds(values[i])) ++met;
    if (!per_run.Holds(values[i])) failed.push_back(seeds[i]);
  }
  std::sort(failed.begin(), failed.end());
  Verdict v;
  if (e.aggregate == Aggregate::Each) {
    v.pass = failed.empty();
    v.value = std::to_string(met) + "/" + std::to_string(total) + " runs";
  } else {
    double share = total ? static_cast<double>(met) / static_cast<double>(total) : 0;
    v.pass = total > 0 && e.check.Holds(share);
    v.value = Short(share) + " (" + std::to_string(met) + "/" + std::to_string(total) + ")";
  }
  v.failed_seeds = std::move(failed);
  return v;
}

/// errors, ticks, summary.KEY, metrics.KEY or KEY.
std::optional<double> NamedValue(const SeedOutcome& run, const std::string& name) {
  if (name == "errors") return ErrorCount(run);
  if (name == "ticks") return NumberOf(run.summary.Find("ticks"));
  if (name.rfind("summary.", 0) == 0) return NumberOf(Lookup(run.summary, name.substr(8)));
  if (name.rfind("metrics.", 0) == 0) return NumberOf(Lookup(run.metrics, name.substr(8)));
  return NumberOf(Lookup(run.metrics, name));
}
}  // namespace

std::optional<double> RunValue(const SeedOutcome& run, const std::string& name) {
  std::string why;
  return RunValue(run, name, &why);
}

std::optional<double> RunValue(const SeedOutcome& run, const std::string& name, std::string* why) {
  size_t slash = RatioSlash(name);
  if (slash != std::string::npos) {  // a share: A/B, e.g. trips_per_source.A/trips_total
    std::optional<double> a = RunValue(run, name.substr(0, slash), why);
    std::optional<double> b = RunValue(run, name.substr(slash + 1), why);
    if (a && b && *b == 0 && why->empty()) *why = "the divisor " + name.substr(slash + 1) + " is 0";
    if (!a || !b || *b == 0) return std::nullopt;
    return *a / *b;
  }
  if (IsFileValue(name)) return FileColumnValue(run.folder, name, why);
  std::optional<double> v = NamedValue(run, name);
  if (!v && why->empty()) *why = WhyNoValue(run, name);
  return v;
}

Verdict Evaluate(const Expectation& e, const std::vector<SeedOutcome>& runs) {
  std::vector<double> values;
  std::vector<uint64_t> seeds, missing;
  std::vector<std::string> notes;
  for (const SeedOutcome& run : runs) {
    std::string why;
    std::optional<double> v = RunValue(run, e.value, &why);
    if (v) values.push_back(*v), seeds.push_back(run.seed);
    if (!v) missing.push_back(run.seed);
    if (!v && !why.empty() && run.failure.empty())  // a failed run is explained by the first row
      notes.push_back("seed " + std::to_string(run.seed) + ": " + why);
  }
  if (e.aggregate == Aggregate::Each || e.aggregate == Aggregate::Fraction) {
    Verdict v = CountRuns(e, values, seeds, missing);
    v.notes = notes;
    return v;
  }
  Verdict v;
  v.notes = notes;
  v.failed_seeds = missing;
  if (values.empty() || !missing.empty()) {
    v.value = "'" + e.value + "' missing in " + std::to_string(missing.size()) + " run(s)";
    return v;
  }
  double aggregate = AggregateOf(e, values);
  v.pass = e.check.Holds(aggregate);
  v.value = Short(aggregate);
  // The runs that pull it the wrong way: those whose own value fails the same comparison.
  for (size_t i = 0; i < values.size() && !v.pass; ++i)
    if (!e.check.Holds(values[i])) v.failed_seeds.push_back(seeds[i]);
  return v;
}

}  // namespace essaim
