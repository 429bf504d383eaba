#include "core/alt_stack.h"

#include <signal.h>

#include <cstddef>
#include <memory>

namespace essaim {

namespace {
// This thread's stack: unregistered before it is freed, when the thread ends.
struct AltStack {
  std::unique_ptr<char[]> memory;
  ~AltStack() {
    if (!memory) return;
    stack_t current{};
    if (sigaltstack(nullptr, &current) == 0 && current.ss_sp == memory.get()) {
      stack_t off{};
      off.ss_flags = SS_DISABLE;
      sigaltstack(&off, nullptr);
    }
  }
};
}  // namespace

void UseAlternateSignalStack() {
  constexpr size_t kSize = 64 * 1024;  // above SIGSTKSZ: the handler formats and writes a summary
  static thread_local AltStack stack;
  if (stack.memory) return;
  // A thread that has one already (the sanitizers give each thread theirs, and free it
  // themselves) keeps it.
  stack_t current{};
  if (sigaltstack(nullptr, &current) == 0 && !(current.ss_flags & SS_DISABLE)) return;
  stack.memory.reset(new char[kSize]);
  stack_t ss{};
  ss.ss_sp = stack.memory.get();
  ss.ss_size = kSize;
  ss.ss_flags = 0;
  sigaltstack(&ss, nullptr);
}

}  // namespace essaim
