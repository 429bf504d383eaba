// An alternate signal stack for the calling thread (sigaltstack), so that a crash handler can
// still run after a stack overflow there (a controller recursing without end). Each thread
// that runs user code makes one once; it lives as long as the thread.
#pragma once

namespace essaim {

void UseAlternateSignalStack();

}  // namespace essaim
