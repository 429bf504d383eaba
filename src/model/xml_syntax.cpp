#include "model/xml_syntax.h"

#include <tinyxml2.h>

namespace essaim {

namespace {
// The element tinyxml2 names at the end of its text ("...: XMLElement name=output"), or "".
std::string NamedElement(const tinyxml2::XMLDocument& doc) {
  const std::string raw = doc.ErrorStr() ? doc.ErrorStr() : "";
  const std::string marker = "XMLElement name=";
  const size_t at = raw.rfind(marker);
  return at == std::string::npos ? "" : raw.substr(at + marker.size());
}
}  // namespace

std::string XmlSyntaxError(const tinyxml2::XMLDocument& doc) {
  using namespace tinyxml2;
  const std::string element = NamedElement(doc);
  const std::string tag = element.empty() ? "an element" : "<" + element + ">";
  switch (doc.ErrorID()) {
    case XML_ERROR_MISMATCHED_ELEMENT:
      return "malformed XML: " + tag + " opened on this line is not closed where it should be: its </" +
             (element.empty() ? "..." : element) + "> is missing, or another element's closing tag comes first";
    case XML_ERROR_PARSING_ATTRIBUTE:
      return "malformed XML: an attribute of " + tag +
             " cannot be read (write each as name=\"value\", quotes on both sides)";
    case XML_ERROR_PARSING_ELEMENT:
      return "malformed XML: " + tag + " is not finished (a '>' or '/>' missing?)";
    case XML_ERROR_PARSING_COMMENT:
      return "malformed XML: a comment '<!--' is not closed with '-->'";
    case XML_ERROR_EMPTY_DOCUMENT:
      return "the file is empty: an experiment is an XML file with an <argos-configuration> element";
    case XML_ERROR_PARSING_DECLARATION:
      return "malformed XML: the declaration '<?xml ... ?>' is not closed";
    case XML_ERROR_PARSING:
      return "malformed XML: an element is not closed by the end of the file, or text there is not XML";
    default:
      return "malformed XML: " + std::string(doc.ErrorName()) + (element.empty() ? "" : " in " + tag);
  }
}

}  // namespace essaim
