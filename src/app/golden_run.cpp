#include "app/golden_run.h"

#include <fstream>
#include <map>

#include "core/hash.h"
#include "core/paths.h"
#include "core/value_json.h"

namespace essaim {

namespace {
/// Every leaf of `v` as "prefix.key" -> its JSON text, so that a difference names its path.
void Flatten(const Value& v, const std::string& prefix, std::map<std::string, std::string>* out) {
  if (v.kind == Value::Kind::Map && !v.map.empty()) {
    for (const auto& [key, child] : v.map) Flatten(child, prefix + "." + key, out);
    return;
  }
  (*out)[prefix] = ValueJsonLine(v);
}

std::string RecordingHash(const std::string& folder) {
  std::string bytes;
  if (!ReadFile(folder + "/recording.bin", &bytes)) return "";
  Fnv1a64 h;
  h.Add(bytes.data(), bytes.size());
  return "fnv1a64:" + h.Hex();
}

Value GoldenOf(const SeedOutcome& run, const std::string& folder) {
  const Value* ticks = run.summary.Find("ticks");
  return Value::MapOf({{"seed", Value::OfUnsigned(run.seed)},
                       {"ticks", ticks ? *ticks : Value()},
                       {"recording", Value::OfString(RecordingHash(folder))},
                       {"metrics", run.metrics}});
}

std::vector<std::string> Differences(const Value& before, const Value& after) {
  std::map<std::string, std::string> old_leaves, new_leaves;
  Flatten(before, "", &old_leaves);
  Flatten(after, "", &new_leaves);
  std::vector<std::string> diffs;
  for (const auto& [path, text] : old_leaves) {
    auto it = new_leaves.find(path);
    std::string now = it == new_leaves.end() ? "(absent)" : it->second;
    if (now != text) diffs.push_back(path.substr(1) + ": " + text + " -> " + now);
  }
  for (const auto& [path, text] : new_leaves)
    if (!old_leaves.count(path)) diffs.push_back(path.substr(1) + ": (absent) -> " + text);
  return diffs;
}

bool WriteText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  return static_cast<bool>(out.flush());
}
}  // namespace

GoldenResult CheckGolden(const std::string& golden_file, const SeedOutcome& run, const std::string& run_folder,
                         bool update) {
  GoldenResult result;
  Value now = GoldenOf(run, run_folder);
  if (!run.failure.empty() || now.Find("recording")->text.empty()) {
    result.value = "the golden seed's run failed";
    return result;
  }
  std::string text, error;
  Value before;
  bool have = ReadFile(golden_file, &text) && ParseJsonValue(text, &before, &error);
  result.diffs = have ? Differences(before, now) : std::vector<std::string>{};
  if (update) {
    result.written = WriteText(golden_file, ValueJsonText(now));
    result.pass = result.written;
    result.value = !result.written ? "cannot write " + golden_file
                   : !have         ? "written (new)"
                                   : "written, " + std::to_string(result.diffs.size()) + " change(s)";
    return result;
  }
  result.pass = have && result.diffs.empty();
  result.value = !error.empty()         ? "unreadable golden file: " + error
                 : !have                ? "no golden file (essaim test --update writes it)"
                 : result.diffs.empty() ? "same"
                                        : std::to_string(result.diffs.size()) + " difference(s)";
  return result;
}

}  // namespace essaim
