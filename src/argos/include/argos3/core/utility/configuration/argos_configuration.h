// ARGoS's configuration tree (argos3/core/utility/configuration/argos_configuration.h):
// the <loop_functions> element and its children as Init(TConfigurationNode&) gets them,
// with ticpp's names (ARGoS reads XML with TinyXML++).
#pragma once
#include <argos3/core/utility/configuration/argos_exception.h>
#include <argos3/core/utility/datatypes/datatypes.h>
#include <argos3/core/utility/string_utilities.h>

#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace ticpp {

class Element {
 public:
  Element() = default;
  explicit Element(const std::string& str_value) : m_strValue(str_value) {}
  /// The element's name.
  const std::string& Value() const { return m_strValue; }
  std::string GetText(bool = true) const { return m_strText; }
  void SetText(const std::string& str_text) { m_strText = str_text; }
  bool HasAttribute(const std::string& str_name) const { return Find(str_name) != nullptr; }
  std::string GetAttribute(const std::string& str_name) const {
    const std::string* value = Find(str_name);
    return value ? *value : std::string();
  }
  /// Reads attribute `str_name` into `*pt_value` (a stream read; "true"/"false" for bool).
  template <typename T>
  void GetAttribute(const std::string& str_name, T* pt_value, bool b_throw_if_not_found = true) const;
  void SetAttribute(const std::string& str_name, const std::string& str_value) {
    m_vecAttributes.emplace_back(str_name, str_value);
  }
  const std::vector<std::pair<std::string, std::string>>& Attributes() const { return m_vecAttributes; }
  /// The element's line in its file (TinyXML++'s Row()), and the file: errors name them.
  int Row() const { return m_nRow; }
  const std::string& File() const { return m_strFile; }
  void SetLocation(const std::string& str_file, int n_row) { m_strFile = str_file, m_nRow = n_row; }
  /// Throws the configuration error `str_message` about this element, as "file:row: <name>: message".
  [[noreturn]] void ThrowError(const std::string& str_message) const {
    std::ostringstream cWhere;
    if (!m_strFile.empty()) cWhere << m_strFile << (m_nRow > 0 ? ":" + std::to_string(m_nRow) : "") << ": ";
    throw argos::CARGoSException::Configuration(cWhere.str() + "<" + m_strValue + ">: " + str_message);
  }
  std::vector<Element>& Children() { return m_vecChildren; }
  const std::vector<Element>& Children() const { return m_vecChildren; }
  /// The first child named `str_name`, or null.
  Element* FirstChildElement(const std::string& str_name) {
    for (Element& child : m_vecChildren)
      if (child.m_strValue == str_name) return &child;
    return nullptr;
  }

 private:
  const std::string* Find(const std::string& str_name) const {
    for (const auto& attribute : m_vecAttributes)
      if (attribute.first == str_name) return &attribute.second;
    return nullptr;
  }
  std::string m_strValue, m_strText, m_strFile;
  int m_nRow = 0;
  std::vector<std::pair<std::string, std::string>> m_vecAttributes;
  std::vector<Element> m_vecChildren;
};

/// The children of an element, in order: `for(it = it.begin(&node); it != it.end(); ++it)`.
template <typename T>
class Iterator {
 public:
  Iterator() = default;
  Iterator begin(T* pc_parent) const {
    Iterator it;
    it.m_pcParent = pc_parent, it.m_unIndex = 0;
    return it;
  }
  Iterator end() const {
    Iterator it;
    it.m_pcParent = m_pcParent, it.m_unIndex = m_pcParent ? m_pcParent->Children().size() : 0;
    return it;
  }
  Iterator& operator++() { return ++m_unIndex, *this; }
  bool operator==(const Iterator& it) const { return m_pcParent == it.m_pcParent && m_unIndex == it.m_unIndex; }
  bool operator!=(const Iterator& it) const { return !(*this == it); }
  T* operator->() const { return &m_pcParent->Children()[m_unIndex]; }
  T& operator*() const { return m_pcParent->Children()[m_unIndex]; }
  T* Get() const { return operator->(); }

 private:
  T* m_pcParent = nullptr;
  size_t m_unIndex = 0;
};

namespace internal {
template <typename T>
bool ReadValue(const std::string& str_text, T* pt_value) {
  std::istringstream stream(str_text);
  stream >> *pt_value;
  return !stream.fail();
}
inline bool ReadValue(const std::string& str_text, std::string* pt_value) {
  *pt_value = str_text;
  return true;
}
inline bool ReadValue(const std::string& str_text, bool* pb_value) {
  if (str_text != "true" && str_text != "false") return false;
  *pb_value = str_text == "true";
  return true;
}
}  // namespace internal

template <typename T>
void Element::GetAttribute(const std::string& str_name, T* pt_value, bool b_throw_if_not_found) const {
  const std::string* text = Find(str_name);
  if (!text) {
    if (b_throw_if_not_found) ThrowError("missing attribute '" + str_name + "'");
    return;
  }
  if (!internal::ReadValue(*text, pt_value)) ThrowError("attribute " + str_name + "=\"" + *text + "\" cannot be read");
}

}  // namespace ticpp

namespace argos {

typedef ticpp::Element TConfigurationNode;
typedef ticpp::Iterator<ticpp::Element> TConfigurationNodeIterator;

inline bool NodeExists(TConfigurationNode& t_node, const std::string& str_tag) {
  return t_node.FirstChildElement(str_tag) != nullptr;
}

/// The first child named `str_tag`; throws when there is none.
inline TConfigurationNode& GetNode(TConfigurationNode& t_node, const std::string& str_tag) {
  TConfigurationNode* child = t_node.FirstChildElement(str_tag);
  if (!child) t_node.ThrowError("no child <" + str_tag + ">");
  return *child;
}

inline bool NodeAttributeExists(TConfigurationNode& t_node, const std::string& str_attribute) {
  return t_node.HasAttribute(str_attribute);
}

template <typename T>
void GetNodeAttribute(TConfigurationNode& t_node, const std::string& str_attribute, T& t_buffer) {
  t_node.GetAttribute(str_attribute, &t_buffer, true);
}

template <typename T>
void GetNodeAttributeOrDefault(TConfigurationNode& t_node, const std::string& str_attribute, T& t_buffer,
                               const T& t_default) {
  t_buffer = t_default;
  t_node.GetAttribute(str_attribute, &t_buffer, false);
}

inline void GetNodeText(TConfigurationNode& t_node, std::string& str_buffer) { str_buffer = t_node.GetText(); }

}  // namespace argos
