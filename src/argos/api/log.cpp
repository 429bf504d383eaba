// LOG and LOGERR: a line goes to the running experiment's log (essaim's log sink, as the
// Lua loop functions' log() lines). Outside a hook (a static initialiser, a constructor run
// at load, a thread of the library's own) it waits in the orphan log until an experiment
// takes it (ArgosTakeOrphanLog), so that it too reaches essaim's log.
#include <argos3/core/utility/logging/argos_log.h>

#include <cstdio>
#include <iostream>
#include <mutex>

#include "argos/api/session_state.h"

namespace essaim {
namespace {
struct OrphanLog {
  std::mutex lock;
  std::string lines;  // "<O or E><text>\n" each
  // Lines no experiment took by the end of the process are not lost: the last resort.
  ~OrphanLog() { std::fputs(lines.c_str(), stderr); }
};
OrphanLog& Orphans() {
  static OrphanLog orphans;
  return orphans;
}
}  // namespace

void ArgosTakeOrphanLog(std::string* into) {
  OrphanLog& orphans = Orphans();
  std::lock_guard<std::mutex> hold(orphans.lock);
  if (orphans.lines.empty()) return;
  *into += orphans.lines;
  orphans.lines.clear();
}
}  // namespace essaim

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
    if (session) {
      session->world->Log(m_bError, line);
    } else {
      essaim::OrphanLog& orphans = essaim::Orphans();
      std::lock_guard<std::mutex> hold(orphans.lock);
      orphans.lines += (m_bError ? 'E' : 'O') + line + '\n';
    }
    start = end + 1;
  }
}

}  // namespace argos
