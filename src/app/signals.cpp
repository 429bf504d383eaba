#include "app/signals.h"

#include <unistd.h>

#include <csignal>
#include <cstdio>

#include "lua/host/watchdog.h"

namespace essaim {

namespace {
// A signal handler takes no argument: the one catcher listening is reached through this
// pointer, set by Listen() and cleared when the catcher goes. Both it and what the handler
// touches (two lock-free atomics) are safe to use from a signal handler.
std::atomic<SignalCatcher*> g_listening{nullptr};
static_assert(std::atomic<SignalCatcher*>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "read and written from a signal handler");
}  // namespace

void SignalCatcher::OnSignal(int sig) {
  SignalCatcher* catcher = g_listening.load();
  if (!catcher) return;
  catcher->caught_ = sig;
  if (catcher->watchdog_) catcher->watchdog_->Interrupt();
}

void SignalCatcher::Listen() {
  g_listening = this;
  std::signal(SIGINT, OnSignal);
  std::signal(SIGTERM, OnSignal);
}

SignalCatcher::~SignalCatcher() {
  SignalCatcher* self = this;
  if (g_listening.compare_exchange_strong(self, nullptr)) {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
  }
}

void ExitStuck(const std::string& message) {
  std::fprintf(stderr, "essaim: %s\n", message.c_str());
  std::fflush(stderr);
  _exit(1);
}

}  // namespace essaim
