#include "serve/frame_mailbox.h"

namespace essaim {

void FrameMailbox::Publish(std::string frame) {
  auto next = std::make_shared<const std::string>(std::move(frame));
  {
    std::lock_guard<std::mutex> lock(mutex_);
    frame_.swap(next);
    ++seq_;
  }
  changed_.notify_all();
  // `next` (the replaced frame) is released here, outside the lock.
}

bool FrameMailbox::WaitNewer(uint64_t* seq, Frame* frame, std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!changed_.wait_for(lock, timeout, [&] { return closed_ || seq_ > *seq; }) || closed_) return false;
  *seq = seq_;
  *frame = frame_;
  return true;
}

FrameMailbox::Frame FrameMailbox::Latest(uint64_t* seq) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (seq) *seq = seq_;
  return frame_;
}

void FrameMailbox::Close() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
  }
  changed_.notify_all();
}

bool FrameMailbox::Closed() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return closed_;
}

std::string SseEvent(const std::string& name, const std::string& data) {
  std::string out = "event: " + name + "\n";
  size_t start = 0;
  while (true) {
    size_t end = data.find('\n', start);
    out += "data: " + data.substr(start, end == std::string::npos ? std::string::npos : end - start) + "\n";
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out + "\n";
}

}  // namespace essaim
