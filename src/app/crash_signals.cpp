#include "app/crash_signals.h"

#include <signal.h>

#include "core/alt_stack.h"

namespace essaim {

namespace {
constexpr int kCrashSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL};
}

void CatchCrashSignals(void (*handler)(int)) {
  UseAlternateSignalStack();
  struct sigaction action {};
  action.sa_handler = handler;
  action.sa_flags = SA_ONSTACK | SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  for (int sig : kCrashSignals) sigaction(sig, &action, nullptr);
}

void ReleaseCrashSignals() {
  for (int sig : kCrashSignals) signal(sig, SIG_DFL);
}

const char* CrashSignalName(int sig) {
  switch (sig) {
    case SIGSEGV:
      return "SIGSEGV (segmentation fault)";
    case SIGBUS:
      return "SIGBUS (bus error)";
    case SIGFPE:
      return "SIGFPE (arithmetic exception, such as an integer division by zero)";
    case SIGILL:
      return "SIGILL (illegal instruction)";
    default:
      return "a crash signal";
  }
}

}  // namespace essaim
