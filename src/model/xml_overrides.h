// --set PATH=VALUE on the parsed XML document, before it is interpreted (docs/cli.md).
#pragma once
#include <string>

namespace tinyxml2 {
class XMLDocument;
class XMLElement;
}  // namespace tinyxml2

namespace essaim {

/// Where an override landed, so the loader can check that something reads it.
struct OverrideTarget {
  const tinyxml2::XMLElement* element = nullptr;
  std::string attribute;
};

/// Applies one "path=value" override; returns false with `error` set when the path names
/// no element or the text is malformed. `target` (optional) receives where it landed.
bool ApplyXmlOverride(tinyxml2::XMLDocument& doc, const std::string& assignment, std::string* error,
                      OverrideTarget* target = nullptr);

}  // namespace essaim
