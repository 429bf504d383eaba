// LOG and LOGERR: a line goes to the robot's log while its C++ controller runs on this
// thread (ArgosSession::ControllerLog, which the host empties in robot order), else to the
// running experiment's log (essaim's log sink, as the Lua loop functions' log() lines).
// Each thread buffers its own text until a line ends. Outside a hook (a static initialiser, a constructor run
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

namespace {
// This thread's text not yet flushed, one buffer for LOG and one for LOGERR.
struct SThreadBuffers {
  std::ostringstream cOut, cErr;
};
thread_local SThreadBuffers t_buffers;

// Where one finished line goes: the robot whose controller runs on this thread, else the
// experiment, else the orphan log.
void Deliver(bool b_error, const std::string& str_line) {
  if (const essaim::ArgosControllerCall* call = essaim::CurrentControllerCall()) {
    std::string& strLog = call->slot->log;
    strLog += b_error ? 'E' : 'O';
    strLog += str_line;
    strLog += '\n';
  } else if (essaim::ArgosSession::State* session = essaim::CurrentSession()) {
    session->world->Log(b_error, str_line);
  } else {
    essaim::OrphanLog& orphans = essaim::Orphans();
    std::lock_guard<std::mutex> hold(orphans.lock);
    orphans.lines += (b_error ? 'E' : 'O') + str_line + '\n';
  }
}
}  // namespace

std::ostream& CARGoSLog::GetStream() { return m_bError ? t_buffers.cErr : t_buffers.cOut; }

CARGoSLog& CARGoSLog::operator<<(std::ostream& (*pf_manipulator)(std::ostream&)) {
  using Manipulator = std::ostream& (*)(std::ostream&);
  if (pf_manipulator == static_cast<Manipulator>(std::endl)) {
    GetStream() << '\n';
    Flush();
  } else {
    GetStream() << pf_manipulator;
  }
  return *this;
}

void CARGoSLog::Flush() {
  std::ostringstream& cBuffer = m_bError ? t_buffers.cErr : t_buffers.cOut;
  if (cBuffer.tellp() <= 0) return;  // nothing written: no copy made
  std::string text = cBuffer.str();
  cBuffer.str("");
  if (text.back() == '\n') text.pop_back();
  size_t start = 0;
  while (start <= text.size()) {  // one log line per line of text
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    Deliver(m_bError, text.substr(start, end - start));
    start = end + 1;
  }
}

}  // namespace argos
