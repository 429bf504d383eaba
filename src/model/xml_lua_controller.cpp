// <lua_controller>: one kind of controller, a file of its own: its id, then what every kind
// holds (LoadControllerBody, xml_controllers.cpp), then its script from <params script>.
#include <string>

#include "core/paths.h"
#include "model/xml_loader_impl.h"

namespace essaim::xml_loader {

void Loader::LoadLuaController(const XMLElement* c) {
  ControllerDef def;
  def.id = Required(c, "id");
  def.loc = Loc(c);
  if (Has(c, "library")) Warn(c, "attribute 'library' ignored for a Lua controller");
  if (const XMLElement* par = LoadControllerBody(c, &def)) {
    std::string script = Str(par, "script");
    if (!script.empty()) {
      def.script = ResolvePath(script);
      if (!FileExists(def.script))
        Error(par, "script '" + script + "' not found (looked beside the .argos file and in the working directory)");
    } else {
      // ARGoS loads no script and its robots stand still in silence: never what was meant.
      Error(c, "lua_controller '" + def.id + "' has no script: add <params script=\"file.lua\"/>");
    }
  }
  model_->controllers.push_back(std::move(def));
}

}  // namespace essaim::xml_loader
