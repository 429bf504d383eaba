// <loop_functions>: a Lua script, or C++ loop functions (library and label), with every
// attribute and child as their parameters and the element kept whole for Init.
#include <string>

#include "core/paths.h"
#include "model/xml_loader_impl.h"

namespace essaim::xml_loader {

// C++ loop functions: library="path", found as ARGoS finds it (xml_library.cpp), and
// label="..."; a label alone is looked for in ARGOS_PLUGIN_PATH's libraries when the run starts.
void Loader::LoadCppLoopFunctions(const XMLElement* e, LoopFunctionsDef* lf) {
  ReadAllBelow(e);  // Init(TConfigurationNode&) may read any of them, at any depth
  lf->label = Str(e, "label");
  if (lf->label.empty()) Error(e, "C++ loop functions need label=\"...\" (the REGISTER_LOOP_FUNCTIONS label)");
  const std::string library = Str(e, "library");
  if (!library.empty()) lf->library = ResolveLibrary(e, library);
}

// Every attribute and descendant is the loop functions' own: none is reported as unknown.
void Loader::ReadAllBelow(const XMLElement* e) {
  ledger_.ReadAll(e);
  for (auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) ReadAllBelow(c);
}

void Loader::LoadLoopFunctions(const XMLElement* e) {
  LoopFunctionsDef& lf = model_->loop_functions;
  lf.loc = Loc(e);
  ledger_.ReadAll(e);  // free-form: every attribute is a parameter for the loop functions
  lf.xml = ToXmlNode(e);
  for (auto* a = e->FirstAttribute(); a; a = a->Next()) lf.params[a->Name()] = a->Value();
  // ARGoS hands the whole element to Init(TConfigurationNode&); scripts read its children
  // as experiment.params.<child>.<attribute>.
  for (auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (lf.children.count(c->Name())) continue;
    AttrMap& attrs = lf.children[c->Name()];
    ledger_.ReadAll(c);  // free-form too: the script reads experiment.params.<child>
    for (auto* a = c->FirstAttribute(); a; a = a->Next()) attrs[a->Name()] = a->Value();
  }
  std::string script = Str(e, "script");
  if (script.empty() && (Has(e, "library") || Has(e, "label"))) return LoadCppLoopFunctions(e, &lf);
  if (Has(e, "library")) Error(e, "give script=\"...\" (Lua) or library=\"...\" (C++), not both");
  if (script.empty()) {
    Error(e, "missing attribute 'script' (a Lua file) or 'label' (C++ loop functions; docs/loop-functions.md)");
    return;
  }
  lf.script = ResolvePath(script);
  if (!FileExists(lf.script)) Error(e, "script '" + script + "' not found");
}

}  // namespace essaim::xml_loader
