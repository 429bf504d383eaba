// A C++ controller: an element of <controllers> whose tag is the label a library registers with
// REGISTER_CONTROLLER (<footbot_diffusion_controller id library>). Its id, then what every kind
// holds (LoadControllerBody), then its library, found as ARGoS finds it; the element is kept
// whole, since Init(TConfigurationNode&) gets its <params>, which may read anything below.
#include <string>

#include "model/xml_loader_impl.h"

namespace essaim::xml_loader {

void Loader::LoadCppController(const XMLElement* c) {
  ControllerDef def;
  def.id = Required(c, "id");
  def.loc = Loc(c);
  def.label = c->Name();
  if (const XMLElement* par = LoadControllerBody(c, &def)) ReadAllBelow(par);
  // As ARGoS: library is optional (the label may come from another entry's library, the loop
  // functions' or ARGOS_PLUGIN_PATH's); the label is looked up when a robot needs it.
  const std::string library = Str(c, "library");
  if (Has(c, "library")) def.library = ResolveLibrary(c, library);
  def.xml = ToXmlNode(c);
  model_->controllers.push_back(std::move(def));
}

}  // namespace essaim::xml_loader
