#include "sim/error_groups.h"

#include <algorithm>

namespace essaim {

namespace {
std::string WithoutRobotPrefix(const ControllerError& e) {
  const std::string prefix = "robot " + e.robot + ": ";
  return e.message.compare(0, prefix.size(), prefix) == 0 ? e.message.substr(prefix.size()) : e.message;
}
}  // namespace

std::vector<std::string> GroupControllerErrors(const std::vector<ControllerError>& errors, size_t from) {
  constexpr size_t kIdsShown = 10;
  struct Group {
    std::string key;
    size_t first;
    std::vector<std::string> others;
  };
  std::vector<Group> groups;
  for (size_t i = from; i < errors.size(); ++i) {
    std::string key = WithoutRobotPrefix(errors[i]);
    auto it = std::find_if(groups.begin(), groups.end(), [&](const Group& g) { return g.key == key; });
    if (it == groups.end())
      groups.push_back({std::move(key), i, {}});
    else
      it->others.push_back(errors[i].robot);
  }
  std::vector<std::string> out;
  for (const Group& g : groups) {
    std::string text = errors[g.first].message;
    if (!g.others.empty()) {
      text += "\n(the same error in " + std::to_string(g.others.size()) + " more robot" +
              (g.others.size() > 1 ? "s" : "") + ": ";
      for (size_t k = 0; k < g.others.size() && k < kIdsShown; ++k) text += (k ? ", " : "") + g.others[k];
      if (g.others.size() > kIdsShown) text += ", ...";
      text += ")";
    }
    out.push_back(std::move(text));
  }
  return out;
}

}  // namespace essaim
