// What is wrong with an XML text that tinyxml2 refused, said for a person: which element or
// construct, and what it lacks (tinyxml2's own text is "Error=XML_ERROR_MISMATCHED_ELEMENT
// ErrorID=14 (0xe) Line number=24: XMLElement name=output").
#pragma once
#include <string>

namespace tinyxml2 {
class XMLDocument;
}

namespace essaim {

/// The message for `doc`'s parse error (its line: doc.ErrorLineNum()).
std::string XmlSyntaxError(const tinyxml2::XMLDocument& doc);

}  // namespace essaim
