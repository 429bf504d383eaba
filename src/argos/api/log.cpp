// LOG and LOGERR: a line goes to the running experiment's log (essaim's log sink, as the
// Lua loop functions' log() lines), or to stdout/stderr outside a hook.
#include <argos3/core/utility/logging/argos_log.h>

#include <cstdio>
#include <iostream>

#include "argos/api/session_state.h"

namespace argos {

CARGoSLog LOG(false);
CARGoSLog LOGERR(true);

CARGoSLog& CARGoSLog::operator<<(std::ostream& (*pf_manipulator)(std::ostream&)) {
  using Manipulator = std::ostream& (*)(std::ostream&);
  if (pf_manipulator == static_cast<Manipulator>(std::endl)) {
    m_cBuffer << '\n';
    Flush();
  } else {
    m_cBuffer << pf_manipulator;
  }
  return *this;
}

void CARGoSLog::Flush() {
  std::string text = m_cBuffer.str();
  if (text.empty()) return;
  m_cBuffer.str("");
  if (text.back() == '\n') text.pop_back();
  essaim::ArgosSession::State* session = essaim::CurrentSession();
  size_t start = 0;
  while (start <= text.size()) {  // one log line per line of text
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    if (session)
      session->world->Log(m_bError, line);
    else
      std::fprintf(m_bError ? stderr : stdout, "%s\n", line.c_str());
    start = end + 1;
  }
}

}  // namespace argos
