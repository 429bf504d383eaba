// `essaim debug --serve`: the live page of a debug session. The HTTP server runs in the
// front (threads do not survive the simulation's forks); the live simulation sends it the
// scene and frames over a pipe made before the first fork, which every simulation and
// checkpoint inherits and only the live one writes to (a copy re-simulating after a going
// back publishes nothing until it is live, then the scene and a frame at once).
#pragma once
#include <chrono>
#include <cstdint>
#include <string>

#include "core/value.h"

namespace essaim {

class ViewServer;
class World;

/// The simulation's end: whole messages, written by the live simulation only.
class ViewPublisher {
 public:
  /// From now on scenes and frames go to `fd` (the pipe's write end).
  void Open(int fd) { fd_ = fd; }
  bool Enabled() const { return fd_ >= 0; }
  /// Whether a running frame is due (about 20 per second of wall time).
  bool Due() const;
  /// The scene when the world's layout changed since the last one sent (or `Invalidate`),
  /// then the frame with `debug` ({paused, tick, ...}).
  void Publish(const World& world, Value debug);
  /// The next Publish sends the scene too: this process has just become the live one.
  void Invalidate() { layout_ = ~uint64_t{0}; }

 private:
  void Send(char kind, const std::string& text);

  int fd_ = -1;
  uint64_t layout_ = ~uint64_t{0};
  uint64_t scene_version_ = 0;
  std::chrono::steady_clock::time_point last_;
};

/// The front's end: the pipe read without blocking, its messages handed to `server`.
class ViewFeed {
 public:
  ViewFeed(int fd, ViewServer* server);
  /// Takes what has come; false at the pipe's end (every simulation gone).
  bool Drain();

 private:
  void TakeMessages();

  int fd_;
  ViewServer* server_;
  std::string buffer_;  // a message not whole yet
};

}  // namespace essaim
