// An element of the .argos file (the model's XmlNode) as ARGoS's TConfigurationNode, which
// loop functions' and controllers' Init read, each element knowing its file and line.
#pragma once
#include <argos3/core/utility/configuration/argos_configuration.h>

#include <string>

#include "model/model.h"

namespace essaim {

ticpp::Element ConfigurationTree(const XmlNode& node, const std::string& file);

}  // namespace essaim
