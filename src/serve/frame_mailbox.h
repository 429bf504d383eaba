// Frames from the simulation thread to the pages: one slot, the latest frame wins. The
// simulation only swaps a pointer under a short lock; a slow page skips frames instead of
// queueing them, and never holds the simulation back.
#pragma once
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

namespace essaim {

class FrameMailbox {
 public:
  using Frame = std::shared_ptr<const std::string>;
  void Publish(std::string frame);
  /// Waits up to `timeout` for a frame newer than *seq: true with it and *seq its number;
  /// false on timeout or once closed.
  bool WaitNewer(uint64_t* seq, Frame* frame, std::chrono::milliseconds timeout);
  /// The latest frame (null before the first) and its number.
  Frame Latest(uint64_t* seq = nullptr) const;
  /// Wakes every waiter for good (server shutdown).
  void Close();
  bool Closed() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  Frame frame_;
  uint64_t seq_ = 0;
  bool closed_ = false;
};

/// One server-sent event: "event: NAME\ndata: ...\n\n", each line of `data` its own data:
/// field (a JSON document on one line gives one).
std::string SseEvent(const std::string& name, const std::string& data);

}  // namespace essaim
