// Parameters nothing read: a key given in <params> (or <loop_functions>) or by --set that no
// script looked up is almost always a typo, which would otherwise run with the default.
#include <set>

#include "core/strings.h"
#include "sim/world.h"

namespace essaim {

namespace {
const std::set<std::string> kReadByEssaim = {"script", "label", "library"};

std::string SetBy(const Model& m, const std::string& path) {
  for (const std::string& o : m.overrides)
    if (o.rfind(path + "=", 0) == 0) return o;
  return {};
}

void Report(const Model& m, const std::string& prefix, const std::set<std::string>& unread,
            const std::set<std::string>& read, const std::string& script, const SourceLoc& loc,
            std::vector<UnreadParam>* out) {
  std::vector<std::string> candidates;
  for (const std::string& k : read)
    if (!kReadByEssaim.count(k)) candidates.push_back(k);
  for (const std::string& key : unread) {
    if (read.count(key) || kReadByEssaim.count(key)) continue;
    std::string path = prefix + key;
    out->push_back({path, key, ClosestName(key, candidates), script, SetBy(m, path), loc});
  }
}
}  // namespace

std::vector<UnreadParam> FindUnreadParams(const World& w) {
  const Model& m = w.model;
  std::vector<UnreadParam> out;
  for (size_t c = 0; c < m.controllers.size(); ++c) {
    std::set<std::string> unread, read;
    for (size_t i = 0; i < w.controllers.size(); ++i) {
      if (m.robots[i].controller != static_cast<int>(c)) continue;
      std::vector<std::string> u, r;
      w.controllers[i]->ParamReads(&u, &r);
      unread.insert(u.begin(), u.end());
      read.insert(r.begin(), r.end());
    }
    const ControllerDef& def = m.controllers[c];
    Report(m, "controllers." + def.id + ".params.", unread, read, def.script, def.loc, &out);
  }
  std::vector<std::string> u, r;
  w.loop_functions.ParamReads(&u, &r);
  Report(m, "loop_functions.", {u.begin(), u.end()}, {r.begin(), r.end()}, m.loop_functions.script,
         m.loop_functions.loc, &out);
  return out;
}

}  // namespace essaim
