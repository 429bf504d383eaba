// The one toml++ user: a test spec's TOML text into a TestSpec. Only plain values are read
// (strings, integers, floats, booleans, arrays of them): nothing in a spec is evaluated.
#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <set>

#include "app/test_spec.h"
#include "core/paths.h"
#include "core/strings.h"

namespace essaim {

namespace {
const std::vector<std::string> kKeys = {"experiment", "workdir", "ticks",  "seeds",       "set",        "expect",
                                        "golden",     "timeout", "labels", "golden_seed", "description"};

struct SpecReader {
  const std::string& path;
  TestSpec* spec;
  std::vector<std::string>* errors;

  void Error(const toml::node* node, const std::string& message) {
    int line = node ? static_cast<int>(node->source().begin.line) : 1;
    errors->push_back(path + ":" + std::to_string(line) + ": " + message);
  }

  static int LineOf(const toml::node* node) { return node ? static_cast<int>(node->source().begin.line) : 0; }

  /// A whole number in [min, max] under `key`, or `fallback` when the key is absent.
  int64_t Integer(const toml::table& t, const char* key, int64_t min, int64_t max, int64_t fallback) {
    const toml::node* node = t.get(key);
    if (!node) return fallback;
    std::optional<int64_t> v = node->value_exact<int64_t>();
    if (!v || *v < min || *v > max) {
      Error(node, std::string(key) + ": a whole number from " + std::to_string(min) + " to " + std::to_string(max));
      return fallback;
    }
    return *v;
  }

  std::string Text(const toml::table& t, const char* key) {
    const toml::node* node = t.get(key);
    if (!node) return "";
    if (!node->is_string()) Error(node, std::string(key) + ": a string (in quotes)");
    return node->value_or(std::string());
  }

  void Seeds(const toml::table& t) {
    const toml::node* node = t.get("seeds");
    if (node && node->is_array()) {
      for (const toml::node& seed : *node->as_array()) {
        std::optional<int64_t> v = seed.value_exact<int64_t>();
        if (!v || *v < 0) Error(&seed, "seeds: each seed a whole number, 0 or more");
        if (v && *v >= 0) spec->seeds.push_back(static_cast<uint64_t>(*v));
      }
      if (spec->seeds.empty()) Error(node, "seeds: the list is empty");
      std::vector<uint64_t> sorted = spec->seeds;
      std::sort(sorted.begin(), sorted.end());
      if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
        Error(node, "seeds: a seed is listed twice (its runs would share a folder)");
      return;
    }
    int64_t count = Integer(t, "seeds", 1, 10000, 10);  // seeds = N: seeds 1..N
    for (int64_t s = 1; s <= count; ++s) spec->seeds.push_back(static_cast<uint64_t>(s));
  }

  static std::string ValueText(const toml::node& v) {
    if (v.is_string()) return v.value_or(std::string());
    if (v.is_boolean()) return v.value_or(false) ? "true" : "false";
    if (v.is_integer()) return std::to_string(v.value_or(int64_t{0}));
    char buf[64];
    auto end = std::to_chars(buf, buf + sizeof buf, v.value_or(0.0)).ptr;  // shortest exact text
    return std::string(buf, end);
  }

  void Settings(const toml::table& t) {
    const toml::node* node = t.get("set");
    if (!node) return;
    if (!node->is_table()) return Error(node, "set: a table of PATH = VALUE ([set])");
    for (auto&& [key, value] : *node->as_table()) {
      if (value.is_string() || value.is_boolean() || value.is_integer() || value.is_floating_point())
        spec->sets.push_back({std::string(key.str()), ValueText(value)});
      else
        Error(&value, "set: '" + std::string(key.str()) + "' needs one string, number or boolean");
    }
  }

  void Expectations(const toml::table& t) {
    const toml::node* node = t.get("expect");
    if (!node) return;
    if (!node->is_array()) return Error(node, "expect: a list of strings, e.g. expect = [\"each errors == 0\"]");
    for (const toml::node& e : *node->as_array()) {
      if (!e.is_string()) Error(&e, "expect: each expectation a string");
      if (e.is_string()) spec->expectations.push_back({e.value_or(std::string()), int(e.source().begin.line)});
    }
  }

  void Labels(const toml::table& t) {
    const toml::node* node = t.get("labels");
    if (!node) return;
    if (!node->is_array()) return Error(node, "labels: a list of strings");
    for (const toml::node& l : *node->as_array()) spec->labels.push_back(l.value_or(std::string()));
  }

  void UnknownKeys(const toml::table& t) {
    for (auto&& [key, value] : t) {
      std::string name(key.str());
      if (std::find(kKeys.begin(), kKeys.end(), name) != kKeys.end()) continue;
      std::string hint = ClosestName(name, kKeys);
      Error(&value, "unknown key '" + name + "'" + (hint.empty() ? "" : "; did you mean '" + hint + "'?"));
    }
  }

  void Read(const toml::table& t) {
    UnknownKeys(t);
    std::string folder = DirName(path);
    spec->experiment_line = LineOf(t.get("experiment"));
    spec->workdir_line = LineOf(t.get("workdir"));
    spec->experiment = Text(t, "experiment");
    if (spec->experiment.empty()) Error(nullptr, "experiment: missing (the .argos file, relative to this file)");
    if (!spec->experiment.empty()) spec->experiment = JoinPath(folder, spec->experiment);
    std::string workdir = Text(t, "workdir");
    spec->workdir = workdir.empty() ? (folder.empty() ? "." : folder) : JoinPath(folder, workdir);
    spec->ticks = static_cast<uint64_t>(Integer(t, "ticks", 1, 1000000000000LL, 0));
    Seeds(t);
    spec->timeout_s = static_cast<int>(Integer(t, "timeout", 1, 86400, 600));
    Settings(t);
    Expectations(t);
    Labels(t);
    std::string golden = Text(t, "golden");
    if (!golden.empty()) spec->golden = JoinPath(folder, golden);
    int64_t first = spec->seeds.empty() ? 1 : static_cast<int64_t>(spec->seeds.front());
    spec->golden_seed = static_cast<uint64_t>(Integer(t, "golden_seed", 0, INT64_MAX, first));
    if (!spec->golden.empty() &&
        std::find(spec->seeds.begin(), spec->seeds.end(), spec->golden_seed) == spec->seeds.end())
      Error(t.get("golden_seed"), "golden_seed " + std::to_string(spec->golden_seed) + " is not one of the seeds");
    if (spec->expectations.empty() && spec->golden.empty())
      Error(nullptr, "nothing to check: give expect = [...] or golden = \"FILE.json\"");
  }
};

/// toml++'s description of a syntax error, said in words a spec's writer acts on.
std::string SyntaxInWords(const std::string& raw) {
  static const std::vector<std::pair<std::string, std::string>> kWords = {
      {"unescaped control characters", "a string has no closing quote (a \"...\" ends on the line it starts)"},
      {"could not determine value type",
       "the value after '=' is not a number, true/false, a \"string\" in quotes or a [list]"},
      {"array: encountered end-of-file", "a list opened with '[' is never closed with ']'"},
      {"cannot redefine existing", "this key is given a second time"},
      {"expected comma or closing ']'", "a comma is missing between two items of the list (or its ']')"},
      {"expected value, saw", "'=' has no value after it"},
      {"expected a comment or whitespace", "something follows the value on this line (one KEY = VALUE per line)"},
  };
  for (const auto& [pattern, words] : kWords)
    if (raw.find(pattern) != std::string::npos) return "TOML syntax: " + words;
  const size_t colon = raw.find(": ");  // "Error while parsing X: detail"
  return "TOML syntax: " + (colon == std::string::npos ? raw : raw.substr(colon + 2));
}

/// FILE:LINE:COL: the syntax error in words, then the line as written.
std::string SyntaxError(const std::string& path, const std::string& text, const toml::parse_error& e) {
  const auto line = static_cast<size_t>(e.source().begin.line);
  std::vector<std::string> lines = Split(text, '\n');
  std::string written = line >= 1 && line <= lines.size() ? Trim(lines[line - 1]) : "";
  return path + ":" + std::to_string(line) + ":" + std::to_string(e.source().begin.column) + ": " +
         SyntaxInWords(std::string(e.description())) + (written.empty() ? "" : ": " + written);
}

std::string StemOf(const std::string& path) {
  std::string name = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  if (name.size() > 5 && name.compare(name.size() - 5, 5, ".toml") == 0) name.resize(name.size() - 5);
  return name;
}
}  // namespace

bool LoadTestSpec(const std::string& path, TestSpec* spec, std::vector<std::string>* errors) {
  spec->file = path;
  spec->name = StemOf(path);
  std::string text;
  if (!ReadFile(path, &text)) {
    errors->push_back(path + ": cannot read the test spec");
    return false;
  }
  try {
    toml::table table = toml::parse(text, path);
    SpecReader{path, spec, errors}.Read(table);
  } catch (const toml::parse_error& e) {
    errors->push_back(SyntaxError(path, text, e));
  }
  return errors->empty();
}

}  // namespace essaim
