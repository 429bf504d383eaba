// ARGoS's CMedium (argos3/core/simulator/medium/medium.h): one of the experiment's <media>.
#pragma once
#include <argos3/core/utility/configuration/argos_configuration.h>
#include <argos3/core/utility/datatypes/datatypes.h>

#include <string>

namespace argos {

class CMedium {
 public:
  explicit CMedium(const std::string& str_id) : m_strId(str_id) {}
  virtual ~CMedium() = default;
  const std::string& GetId() const { return m_strId; }

 private:
  std::string m_strId;
};

}  // namespace argos
