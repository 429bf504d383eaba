// The signals a crash raises (SIGSEGV, SIGBUS, SIGFPE, SIGILL): caught on an alternate stack,
// once (a fault inside the handler ends the process as if none were installed).
#pragma once

namespace essaim {

/// Installs `handler` for the crash signals, and an alternate stack for the calling thread.
void CatchCrashSignals(void (*handler)(int));
/// The default action back for every crash signal.
void ReleaseCrashSignals();
/// "SIGSEGV (segmentation fault)".
const char* CrashSignalName(int sig);

}  // namespace essaim
