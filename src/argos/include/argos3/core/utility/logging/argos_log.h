// ARGoS's LOG and LOGERR (argos3/core/utility/logging/argos_log.h): streams whose lines go
// to essaim's log, as the Lua loop functions' log() and logerr() do.
#pragma once
#include <argos3/core/utility/datatypes/datatypes.h>  // ARGoS: through argos_colored_text.h

#include <sstream>
#include <string>

namespace argos {

class CARGoSLog {
 public:
  explicit CARGoSLog(bool b_error) : m_bError(b_error) {}
  template <typename T>
  CARGoSLog& operator<<(const T& t_value) {
    m_cBuffer << t_value;
    return *this;
  }
  /// std::endl ends a line (it goes to the log); other manipulators apply to the text.
  CARGoSLog& operator<<(std::ostream& (*pf_manipulator)(std::ostream&));
  /// Writes what is buffered as a line, if anything.
  void Flush();
  std::ostream& GetStream() { return m_cBuffer; }

 private:
  bool m_bError;
  std::ostringstream m_cBuffer;
};

extern CARGoSLog LOG;
extern CARGoSLog LOGERR;

}  // namespace argos
