// Reading attributes: typed reads through the ledger (what nobody read is unknown), allowed
// children, paths beside the file, and the report of unknown attributes with suggestions.
#include <set>
#include <string>
#include <utility>

#include "core/paths.h"
#include "core/strings.h"
#include "model/xml_loader_impl.h"

namespace essaim::xml_loader {

double Loader::Double(const XMLElement* e, const char* name, double def, bool required) {
  const char* v = Get(e, name);
  if (!v) {
    if (required) Error(e, std::string("missing required attribute '") + name + "'");
    return def;
  }
  auto d = ParseDouble(v);
  if (!d) {
    Error(e, std::string("attribute '") + name + "': '" + v + "' is not a number");
    return def;
  }
  return *d;
}

long long Loader::Int(const XMLElement* e, const char* name, long long def, bool required) {
  const char* v = Get(e, name);
  if (!v) {
    if (required) Error(e, std::string("missing required attribute '") + name + "'");
    return def;
  }
  auto d = ParseInt(v);
  if (!d) {
    Error(e, std::string("attribute '") + name + "': '" + v + "' is not an integer");
    return def;
  }
  return *d;
}

bool Loader::Bool(const XMLElement* e, const char* name, bool def) {
  const char* v = Get(e, name);
  if (!v) return def;
  auto b = ParseBool(v);
  if (!b) {
    Error(e, std::string("attribute '") + name + "': '" + v + "' must be true or false");
    return def;
  }
  return *b;
}

Vec3 Loader::Vector3(const XMLElement* e, const char* name, const Vec3& def, bool required) {
  const char* v = Get(e, name);
  if (!v) {
    if (required) Error(e, std::string("missing required attribute '") + name + "'");
    return def;
  }
  auto d = ParseVector(v, 3);
  if (!d) {
    Error(e, std::string("attribute '") + name + "': '" + v + "' must be three comma-separated numbers");
    return def;
  }
  return {(*d)[0], (*d)[1], (*d)[2]};
}

void Loader::CheckChildren(const XMLElement* e, const std::set<std::string>& allowed, const char* what) {
  ledger_.Visit(e);
  for (auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (allowed.count(c->Name())) continue;
    std::string hint = ClosestName(c->Name(), {allowed.begin(), allowed.end()});
    Error(c, std::string("unknown element inside <") + e->Name() + "> (" +
                 (hint.empty() ? what : "did you mean <" + hint + ">?") + ")");
  }
}

std::string Loader::ResolvePath(const std::string& rel) const {
  if (rel.empty() || rel[0] == '/') return rel;
  std::string beside = JoinPath(dir_, rel);
  if (FileExists(beside)) return beside;
  std::string cwd = JoinPath(options_.working_dir == "." ? "" : options_.working_dir, rel);
  if (FileExists(cwd)) return cwd;
  return beside;  // reported as missing by the caller
}

// Attributes nobody read: an error for a --set (a sweep over it would change nothing), a
// warning in the file (an error under --strict), each with the closest known name.
void Loader::ReportUnknownAttributes(const XMLElement* root) {
  auto hint = [&](const XMLElement* e, const std::string& name) {
    std::string best = ledger_.Suggest(e, name);
    // Read on another element of this tag: a setting that only counts with other values
    // (a box's mass when movable="true", a generator's min with method="uniform").
    if (best == name)
      return std::string("; it counts on other <") + e->Name() + "> elements, not with this one's settings";
    return best.empty() ? std::string() : "; did you mean '" + best + "'?";
  };
  std::set<std::pair<const XMLElement*, std::string>> from_set;
  for (const auto& [target, assignment] : set_targets_) {
    from_set.insert({target.element, target.attribute});
    if (ledger_.Known(target.element, target.attribute)) continue;
    std::string what = ledger_.Visited(target.element)
                           ? "essaim reads no attribute '" + target.attribute + "' on <" + target.element->Name() +
                                 ">" + hint(target.element, target.attribute)
                           : std::string("essaim does not read <") + target.element->Name() + "> or its attributes";
    Error(target.element, "--set " + assignment + ": " + what);
  }
  ledger_.ForEachUnknown(root, [&](const XMLElement* e, const std::string& name) {
    if (from_set.count({e, name})) return;
    std::string msg = "unknown attribute '" + name + "' (essaim does not read it)" + hint(e, name);
    if (std::string(e->Name()) == "experiment") msg += NoEndHint();
    if (options_.strict)
      Error(e, msg);
    else
      Warn(e, msg);
  });
}

// A misspelt length (lenght="60") leaves the run with none: say so where the typo is named,
// or the run goes on with nothing to tell why. Lua is not loaded yet: whether the loop
// functions end the run is not known here.
std::string Loader::NoEndHint() const {
  if (model_->experiment.length_ticks != 0) return "";
  const LoopFunctionsDef& lf = model_->loop_functions;
  if (lf.script.empty() && !lf.Cpp()) return "; with no length, the run has no end (until Ctrl-C; --ticks N sets one)";
  return "; with no length, the run has no end unless the loop functions end it";
}

XmlNode ToXmlNode(const XMLElement* e) {
  XmlNode node;
  node.name = e->Name();
  node.line = e->GetLineNum();
  for (auto* a = e->FirstAttribute(); a; a = a->Next()) node.attributes.emplace_back(a->Name(), a->Value());
  if (e->GetText()) node.text = e->GetText();
  for (auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) node.children.push_back(ToXmlNode(c));
  return node;
}

}  // namespace essaim::xml_loader
