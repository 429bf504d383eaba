// --set PATH=VALUE on the parsed XML document, before it is interpreted (docs/cli.md).
#pragma once
#include <string>

namespace tinyxml2 {
class XMLDocument;
}

namespace essaim {

/// Applies one "path=value" override; returns false with `error` set when the path names
/// no element or the text is malformed.
bool ApplyXmlOverride(tinyxml2::XMLDocument& doc, const std::string& assignment, std::string* error);

}  // namespace essaim
