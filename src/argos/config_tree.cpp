#include "argos/config_tree.h"

namespace essaim {

ticpp::Element ConfigurationTree(const XmlNode& node, const std::string& file) {
  ticpp::Element element(node.name);
  element.SetLocation(file, node.line);
  for (const auto& attribute : node.attributes) element.SetAttribute(attribute.first, attribute.second);
  element.SetText(node.text);
  for (const XmlNode& child : node.children) element.Children().push_back(ConfigurationTree(child, file));
  return element;
}

}  // namespace essaim
