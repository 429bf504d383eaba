#include "model/xml_overrides.h"

#include <tinyxml2.h>

#include "core/strings.h"

namespace essaim {

namespace {
// One path segment: "tag", "tag[k]" or an element id.
tinyxml2::XMLElement* FindChild(tinyxml2::XMLElement* parent, const std::string& segment) {
  std::string name = segment;
  long long index = -1;
  size_t bracket = segment.find('[');
  if (bracket != std::string::npos && segment.back() == ']') {
    name = segment.substr(0, bracket);
    auto k = ParseInt(segment.substr(bracket + 1, segment.size() - bracket - 2));
    if (!k || *k < 0) return nullptr;
    index = *k;
  }
  long long seen = 0;
  for (auto* c = parent->FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (name == c->Name()) {
      if (index < 0 || seen == index) return c;
      ++seen;
    }
  }
  if (index >= 0) return nullptr;
  for (auto* c = parent->FirstChildElement(); c; c = c->NextSiblingElement()) {
    const char* id = c->Attribute("id");
    if (id && name == id) return c;
  }
  return nullptr;
}

// The names a segment could have meant: the children's tags and ids.
std::string ClosestChild(const tinyxml2::XMLElement* parent, const std::string& segment) {
  std::vector<std::string> names;
  for (auto* c = parent->FirstChildElement(); c; c = c->NextSiblingElement()) {
    names.push_back(c->Name());
    if (const char* id = c->Attribute("id")) names.push_back(id);
  }
  std::string hint = ClosestName(segment.substr(0, segment.find('[')), names);
  return hint.empty() ? "" : "; did you mean '" + hint + "'?";
}
}  // namespace

bool ApplyXmlOverride(tinyxml2::XMLDocument& doc, const std::string& assignment, std::string* error,
                      OverrideTarget* target) {
  size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    *error = "--set " + assignment + ": expected PATH=VALUE";
    return false;
  }
  std::string path = assignment.substr(0, eq), value = assignment.substr(eq + 1);
  std::vector<std::string> segments = Split(path, '.');
  if (segments.size() < 2) {
    *error = "--set " + assignment + ": PATH needs at least an element and an attribute";
    return false;
  }
  tinyxml2::XMLElement* node = doc.RootElement();
  if (!node) {
    *error = "--set " + assignment + ": the document has no root element";
    return false;
  }
  std::string walked;
  for (size_t i = 0; i + 1 < segments.size(); ++i) {
    walked += (i ? "." : "") + segments[i];
    tinyxml2::XMLElement* child = FindChild(node, segments[i]);
    if (!child) {
      *error = "--set " + assignment + ": no element at '" + walked + "'" + ClosestChild(node, segments[i]);
      return false;
    }
    node = child;
  }
  node->SetAttribute(segments.back().c_str(), value.c_str());
  if (target) *target = {node, segments.back()};
  return true;
}

}  // namespace essaim
