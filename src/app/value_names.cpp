#include "app/value_names.h"

#include <algorithm>

#include "app/file_column.h"
#include "core/paths.h"
#include "core/strings.h"

namespace essaim {

namespace {
bool IsNumber(const Value& v) {
  return v.kind == Value::Kind::Bool || v.kind == Value::Kind::Integer || v.kind == Value::Kind::Unsigned ||
         v.kind == Value::Kind::Number;
}

/// The dotted paths of every number below `v`, each prefixed.
void NumberPaths(const Value& v, const std::string& prefix, std::vector<std::string>* out) {
  if (IsNumber(v) && !prefix.empty()) out->push_back(prefix);
  if (v.kind != Value::Kind::Map) return;
  for (const auto& [key, child] : v.map) NumberPaths(child, prefix.empty() ? key : prefix + "." + key, out);
}

/// Where `name` reads: the file's label, its root in the run and the key below it.
struct Source {
  const char* file;
  const Value* root;
  std::string key;
};

Source SourceOf(const SeedOutcome& run, const std::string& name) {
  if (name.rfind("summary.", 0) == 0) return {"summary.json", &run.summary, name.substr(8)};
  if (name.rfind("metrics.", 0) == 0) return {"metrics.json", &run.metrics, name.substr(8)};
  return {"metrics.json", &run.metrics, name};
}

const Value* Lookup(const Value& root, const std::string& dotted) {
  const Value* v = &root;
  for (const std::string& key : Split(dotted, '.'))
    if (!(v = v->Find(key))) return nullptr;
  return v;
}

bool IsBuiltIn(const std::string& name) { return name == "errors" || name == "ticks" || IsFileValue(name); }

/// Every name the runs give an expectation, as it would be written.
std::vector<std::string> NamesIn(const std::vector<SeedOutcome>& runs) {
  std::vector<std::string> names = {"errors", "ticks"};
  for (const SeedOutcome& run : runs) {
    NumberPaths(run.metrics, "", &names);
    NumberPaths(run.summary, "summary", &names);
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

/// The columns of the run's timeseries.csv (its header row), if it wrote one.
std::vector<std::string> TimeSeriesColumns(const SeedOutcome& run) {
  std::string text;
  if (run.folder.empty() || !ReadFile(run.folder + "/timeseries.csv", &text)) return {};
  std::vector<std::string> columns;
  for (const std::string& c : Split(text.substr(0, text.find('\n')), ',')) columns.push_back(Trim(c));
  return columns;
}

/// A name the runs wrote where an expectation cannot read it: a column of timeseries.csv.
std::string TimeSeriesHint(const std::string& bare, const std::vector<SeedOutcome>& runs) {
  std::vector<std::string> columns = TimeSeriesColumns(runs.front());
  std::string column =
      std::find(columns.begin(), columns.end(), bare) != columns.end() ? bare : ClosestName(bare, columns);
  if (column.empty()) return "";
  return "; '" + column + "' is a column of timeseries.csv, which an expectation does not read: return it " +
         "from post_experiment() to make it a metric";
}

/// "(A, B, C)": the first keys of an object, for a hint.
std::string KeysOf(const std::string& name, const Value& object) {
  std::string keys;
  for (size_t i = 0; i < object.map.size() && i < 3; ++i) keys += (i ? ", " : "") + name + "." + object.map[i].first;
  return keys.empty() ? name + ".KEY" : keys;
}

/// One side of a ratio that no run produced: the message, or "".
std::string UnknownName(const std::string& name, const std::vector<SeedOutcome>& runs) {
  if (IsBuiltIn(name)) return "";
  for (const SeedOutcome& run : runs)
    if (WhyNoValue(run, name).empty()) return "";
  const Source first = SourceOf(runs.front(), name);
  for (const SeedOutcome& run : runs) {
    const Value* found = Lookup(*SourceOf(run, name).root, first.key);
    if (found && found->kind == Value::Kind::Map)
      return "'" + name + "' is an object in " + first.file + ", not a number: name one of its keys (" +
             KeysOf(name, *found) + ")";
  }
  bool any_file =
      std::any_of(runs.begin(), runs.end(), [&](const SeedOutcome& r) { return !SourceOf(r, name).root->IsNull(); });
  std::string where = any_file ? std::string(first.file) : "the runs wrote no " + std::string(first.file);
  std::string bare = name.rfind("metrics.", 0) == 0 ? name.substr(8) : name;
  std::string hint = ClosestName(bare, NamesIn(runs));
  return "no run produced '" + name + "' (" + where + ")" +
         (hint.empty() ? TimeSeriesHint(bare, runs) : "; did you mean '" + hint + "'?");
}
}  // namespace

std::string WhyNoValue(const SeedOutcome& run, const std::string& name) {
  if (IsBuiltIn(name)) return "";
  Source s = SourceOf(run, name);
  if (s.root->IsNull()) return std::string("the run wrote no ") + s.file;
  const Value* v = Lookup(*s.root, s.key);
  if (!v) return std::string(s.file) + " has no '" + s.key + "'";
  if (!IsNumber(*v)) return "'" + name + "' is not a number in " + s.file;
  return "";
}

std::string UnknownValueError(const std::string& value, const std::vector<SeedOutcome>& runs) {
  if (runs.empty()) return "";
  const size_t slash = RatioSlash(value);
  if (slash == std::string::npos) return UnknownName(value, runs);
  std::string a = UnknownName(value.substr(0, slash), runs);
  std::string b = UnknownName(value.substr(slash + 1), runs);
  return a.empty() ? b : b.empty() ? a : a + "; " + b;
}

}  // namespace essaim
