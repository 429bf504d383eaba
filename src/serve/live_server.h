// `essaim serve`: the simulation on the calling thread, an HTTP server on its own threads,
// and between them a queue of commands, the latest frame (FrameMailbox), the log and the
// time series. Pages and scripts never touch the World: the simulation thread answers
// them between ticks, and never waits for them.
#pragma once
#include <atomic>
#include <functional>
#include <memory>
#include <string>

#include "model/xml_loader.h"

namespace essaim {

class Watchdog;

struct ServeOptions {
  std::string file;
  LoadOptions load;
  std::string host = "127.0.0.1";
  int port = 8765;
  std::string token;  // "" : a fresh random one
  /// The page's HTML, with the drawing and chart code already in it.
  std::string page;
  /// The watchdog of every experiment's Lua states (the command's, which signals reach).
  Watchdog* watchdog = nullptr;
  /// Told what a person watching the command should know (a load failed, a file changed, a
  /// reload's run number), a message without a trailing newline (a failed load's has the
  /// error's lines after the first); the command prints it. Unset: nothing is said.
  std::function<void(const std::string&)> report;
};

class LiveServer {
 public:
  explicit LiveServer(ServeOptions options);
  ~LiveServer();
  /// Loads the experiment (an error is shown on the page, not fatal), starts watching its
  /// files and listening. False with `error` when the port cannot be bound or inotify
  /// cannot be used.
  bool Start(std::string* error);
  /// http://HOST:PORT/?token=TOKEN
  std::string Url() const;
  /// Runs the simulation loop until `stop` is non-zero, then stops the server.
  void Run(const std::atomic<int>& stop);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace essaim
