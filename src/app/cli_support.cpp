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
