#include "debug/debug_view.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/fd_io.h"
#include "debug/dap_channel.h"
#include "serve/live_experiment.h"
#include "serve/view_server.h"
#include "sim/world.h"

namespace essaim {

namespace {
constexpr auto kFrameInterval = std::chrono::milliseconds(50);

// A message: its kind ('S' scene, 'F' frame), its length, then its JSON text.
struct Header {
  char kind;
  uint32_t size;
};
}  // namespace

bool ViewPublisher::Due() const { return std::chrono::steady_clock::now() - last_ >= kFrameInterval; }

void ViewPublisher::Send(char kind, const std::string& text) {
  Header h{};
  h.kind = kind;
  h.size = static_cast<uint32_t>(text.size());
  // One writer at a time (the live simulation), so a message is never interleaved; a
  // front gone (EPIPE) ends the session anyway.
  if (WriteAll(fd_, &h, sizeof h)) WriteAll(fd_, text.data(), text.size());
}

void ViewPublisher::Publish(const World& world, Value debug) {
  if (fd_ < 0) return;
  last_ = std::chrono::steady_clock::now();
  if (world.entities.LayoutVersion() != layout_) {
    layout_ = world.entities.LayoutVersion();
    // The version must differ from any other process's: a copy woken from a checkpoint
    // counts from where the checkpoint was. Monotonic clock time does, across processes.
    scene_version_ =
        static_cast<uint64_t>(std::chrono::duration_cast<std::chrono::microseconds>(last_.time_since_epoch()).count());
    Send('S', SceneText(world));
  }
  FrameInfo info;
  info.run = 1;
  info.paused = BoolField(debug, "paused");
  info.speed = 0;
  info.scene = scene_version_;
  info.debug = std::move(debug);
  Send('F', FrameText(world, info));
}

ViewFeed::ViewFeed(int fd, ViewServer* server) : fd_(fd), server_(server) { fcntl(fd_, F_SETFL, O_NONBLOCK); }

bool ViewFeed::Drain() {
  char chunk[65536];
  while (true) {
    const ssize_t n = read(fd_, chunk, sizeof chunk);
    if (n > 0) {
      buffer_.append(chunk, static_cast<size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    TakeMessages();
    return n < 0 && errno == EAGAIN;
  }
}

void ViewFeed::TakeMessages() {
  size_t at = 0;
  Header h{};
  while (buffer_.size() - at >= sizeof h) {
    std::memcpy(&h, buffer_.data() + at, sizeof h);
    if (buffer_.size() - at - sizeof h < h.size) break;
    std::string text = buffer_.substr(at + sizeof h, h.size);
    at += sizeof h + h.size;
    if (h.kind == 'S')
      server_->SetScene(std::move(text));
    else
      server_->Frames().Publish(std::move(text));
  }
  buffer_.erase(0, at);
}

}  // namespace essaim
