#include "model/attribute_ledger.h"

#include <tinyxml2.h>

#include "core/strings.h"

namespace essaim {

const std::vector<std::string>& KnownIgnoredAttributes(const std::string& tag) {
  // ARGoS reads these; essaim has nothing to do with them (headless, one physics engine,
  // no perspective camera, no profiler). Attributes essaim warns about when set (real_time,
  // positional_index, library, a battery's model) are read by the loader, so not listed.
  static const std::map<std::string, std::vector<std::string>> kIgnored = {
      {"system", {"pin_threads_to_cores"}},
      {"profiling", {"file", "format", "truncate_file"}},
      {"arena", {"positional_grid_size"}},
      {"foot-bot",
       {"perspective_camera_front", "perspective_camera_aperture", "perspective_camera_focal_length",
        "perspective_camera_range"}},
      {"led", {"anchor", "index", "grid_size"}},
      {"range_and_bearing", {"grid_size"}},
      {"spatial_hash", {"cell_size", "cell_num"}},
  };
  static const std::vector<std::string> kNone;
  auto it = kIgnored.find(tag);
  return it == kIgnored.end() ? kNone : it->second;
}

void AttributeLedger::Read(const Element* e, const char* name) {
  read_[e].insert(name);
  by_tag_[e->Name()].insert(name);
}

void AttributeLedger::ReadAll(const Element* e) {
  Visit(e);
  read_all_.insert(e);
}

void AttributeLedger::Visit(const Element* e) { read_[e]; }

bool AttributeLedger::Known(const Element* e, const std::string& name) const {
  if (read_all_.count(e)) return true;
  // XML namespaces and schema hints (xmlns:xsi, xsi:noNamespaceSchemaLocation) are the
  // file's business, not the simulator's.
  if (name.rfind("xmlns", 0) == 0 || name.find(':') != std::string::npos) return true;
  auto it = read_.find(e);
  if (it != read_.end() && it->second.count(name)) return true;
  for (const std::string& n : KnownIgnoredAttributes(e->Name()))
    if (n == name) return true;
  return false;
}

std::string AttributeLedger::Suggest(const Element* e, const std::string& name) const {
  std::vector<std::string> candidates = KnownIgnoredAttributes(e->Name());
  auto it = by_tag_.find(e->Name());
  if (it != by_tag_.end()) candidates.insert(candidates.end(), it->second.begin(), it->second.end());
  return ClosestName(name, candidates);
}

void AttributeLedger::ForEachUnknown(const Element* root,
                                     const std::function<void(const Element*, const std::string&)>& unread) const {
  if (!Visited(root)) return;  // ignored whole (<visualization>), or already an error
  for (const tinyxml2::XMLAttribute* a = root->FirstAttribute(); a; a = a->Next())
    if (!Known(root, a->Name())) unread(root, a->Name());
  for (const Element* c = root->FirstChildElement(); c; c = c->NextSiblingElement()) ForEachUnknown(c, unread);
}

}  // namespace essaim
