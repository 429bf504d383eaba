#include "core/alt_stack.h"

#include <signal.h>

#include <cstddef>
#include <memory>

namespace essaim {

void UseAlternateSignalStack() {
  constexpr size_t kSize = 64 * 1024;  // above SIGSTKSZ: the handler formats and writes a summary
  static thread_local std::unique_ptr<char[]> stack;
  if (stack) return;
  stack.reset(new char[kSize]);
  stack_t ss{};
  ss.ss_sp = stack.get();
  ss.ss_size = kSize;
  ss.ss_flags = 0;
  sigaltstack(&ss, nullptr);
}

}  // namespace essaim
