// ARGoS's LOG and LOGERR (argos3/core/utility/logging/argos_log.h): streams whose lines go
// to essaim's log, as the Lua loop functions' log() and logerr() do; written from a robot's
// C++ controller, to that robot's log. Each thread writes into a buffer of its own, so
// controllers stepped at once on several threads do not mix their lines.
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
    GetStream() << t_value;
    return *this;
  }
  /// std::endl ends a line (it goes to the log); other manipulators apply to the text.
  CARGoSLog& operator<<(std::ostream& (*pf_manipulator)(std::ostream&));
  /// Writes what is buffered as a line, if anything.
  void Flush();
  /// This thread's buffer of this log.
  std::ostream& GetStream();

 private:
  bool m_bError;
};

extern CARGoSLog LOG;
extern CARGoSLog LOGERR;

}  // namespace argos

/// LOG and LOGERR prefixed with "[<id>] ": inside a controller's (or an entity's) member
/// functions, where GetId() is its id.
#define RLOG argos::LOG << "[" << GetId() << "] "
#define RLOGERR argos::LOGERR << "[" << GetId() << "] "
