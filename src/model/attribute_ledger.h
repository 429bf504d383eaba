// Which attributes the loader read on which element. Whatever a file (or --set) holds beyond
// that is read by nobody: a typo that would otherwise change nothing, in silence. The known
// attributes are the loader's own reads, so this list cannot drift from the loader.
#pragma once
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace tinyxml2 {
class XMLElement;
}

namespace essaim {

class AttributeLedger {
 public:
  using Element = tinyxml2::XMLElement;
  /// The loader asked for attribute `name` of `e`, present or not.
  void Read(const Element* e, const char* name);
  /// Every attribute of `e` is used (free-form <params>, loop-function parameters).
  void ReadAll(const Element* e);
  /// The loader looked at `e` (its children, its presence) without reading an attribute.
  void Visit(const Element* e);

  bool Visited(const Element* e) const { return read_.count(e) > 0; }
  /// Read on `e`, or accepted on that tag and ignored on purpose (KnownIgnoredAttributes).
  bool Known(const Element* e, const std::string& name) const;
  /// The known name closest to `name` for `e`'s tag, or "" (for "did you mean").
  std::string Suggest(const Element* e, const std::string& name) const;
  /// Calls `unread(element, attribute)` for each attribute nobody reads, on every visited
  /// element below and including `root`, in document order.
  void ForEachUnknown(const Element* root, const std::function<void(const Element*, const std::string&)>& unread) const;

 private:
  std::map<const Element*, std::set<std::string>> read_;
  std::map<std::string, std::set<std::string>> by_tag_;  // every name read on any element of a tag
  std::set<const Element*> read_all_;
};

/// Attributes ARGoS accepts that essaim ignores on purpose (docs/compatibility.md),
/// by element tag: never reported as typos.
const std::vector<std::string>& KnownIgnoredAttributes(const std::string& tag);

}  // namespace essaim
