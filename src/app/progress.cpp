#include <chrono>
#include <cstdio>

#include "app/commands.h"

namespace essaim {

namespace {
double Now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

Progress::Progress(bool enabled, unsigned long long total, size_t robots)
    : enabled_(enabled), total_(total), robots_(robots), start_(Now()), last_(0) {}

void Progress::Update(unsigned long long tick) {
  if (!enabled_) return;
  double now = Now();
  if (now - last_ < 0.25) return;
  last_ = now;
  double rate = tick / std::max(1e-9, now - start_);
  if (total_ > 0) {
    double eta = (total_ - tick) / std::max(1e-9, rate);
    std::fprintf(stderr, "\r  tick %llu/%llu (%3.0f%%)  %.0f ticks/s  %zu robots  ETA %.0fs   ", tick, total_,
                 100.0 * tick / total_, rate, robots_, eta);
  } else {
    std::fprintf(stderr, "\r  tick %llu  %.0f ticks/s  %zu robots   ", tick, rate, robots_);
  }
  std::fflush(stderr);
  shown_ = true;
}

void Progress::Clear() {
  if (!enabled_ || !shown_) return;
  std::fprintf(stderr, "\r%*s\r", 79, "");
  std::fflush(stderr);
  shown_ = false;
}

void Progress::Finish() { Clear(); }

}  // namespace essaim
