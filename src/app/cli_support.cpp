#include "app/cli_support.h"

#include <algorithm>
#include <cstdio>

#include "core/strings.h"

namespace essaim {

CLI::Validator IntegerIn(long long min, long long max, const std::string& why) {
  std::string range = std::to_string(min) + " to " + std::to_string(max);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        auto n = ParseInt(text);
        if (!n) return "'" + text + "' is not a whole number (expected " + range + ")";
        if (*n < min || *n > max)
          return "'" + text + "' is out of range: expected " + range + (why.empty() ? "" : " (" + why + ")");
        return "";
      },
      "");  // the option's help text says the range in words
}

namespace {
// Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
// neighbours ("tikcs" is one edit from "ticks").
size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

std::string WithoutDashes(const std::string& s) { return s.substr(std::min(s.find_first_not_of('-'), s.size())); }
}  // namespace

std::string ClosestName(const std::string& typed, const std::vector<std::string>& candidates) {
  std::string core = WithoutDashes(typed), best;
  if (core.size() < 3) return best;  // "-q" is one letter from every short option
  size_t best_d = std::max<size_t>(1, core.size() / 3) + 1;  // farther than this is no suggestion
  for (const std::string& c : candidates) {
    size_t d = EditDistance(core, WithoutDashes(c));
    if (d < best_d) best_d = d, best = c;
  }
  return best;
}

std::vector<std::string> OptionNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : o->get_snames()) names.push_back("-" + s);
  }
  return names;
}

bool ReportLeftovers(const CLI::App& sub, const std::string& prog) {
  std::vector<std::string> rest = sub.remaining();
  if (rest.empty()) return false;
  const std::string& a = rest.front();
  if (a.size() > 1 && a[0] == '-') {
    std::string name = a.substr(0, a.find('='));
    std::string hint = ClosestName(name, OptionNames(sub));
    std::fprintf(stderr, "%s: unknown option %s%s\n", prog.c_str(), name.c_str(),
                 hint.empty() ? "" : (" (did you mean " + hint + "?)").c_str());
  } else {
    std::fprintf(stderr, "%s: unexpected argument %s\n", prog.c_str(), a.c_str());
  }
  std::fprintf(stderr, "see '%s --help'\n", prog.c_str());
  return true;
}

}  // namespace essaim
