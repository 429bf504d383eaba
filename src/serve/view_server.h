// The live page's server without the simulation: the page, /api/state (the latest frame),
// /api/scene and /api/events behind the token, fed by whoever simulates. `essaim serve`
// adds its control and inspection routes; `essaim debug --serve` feeds it from another
// process (src/debug/debug_view.h).
#pragma once
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "serve/access.h"
#include "serve/frame_mailbox.h"
#include "serve/http_server.h"

namespace essaim {

class ViewServer {
 public:
  explicit ViewServer(std::string page);
  ~ViewServer();
  ViewServer(const ViewServer&) = delete;
  ViewServer& operator=(const ViewServer&) = delete;

  /// For more routes, added before Start.
  HttpServer& Http() { return http_; }
  FrameMailbox& Frames() { return frames_; }
  void SetScene(std::string scene_json);
  /// Listens on `host`:`port` (0: a free one) with `token` ("" : a fresh one), serving on
  /// threads of its own; false with `error`.
  bool Start(const std::string& host, int port, const std::string& token, std::string* error);
  /// http://HOST:PORT/?token=TOKEN
  std::string Url(const std::string& host) const;
  /// Ends every event stream and the server.
  void Stop();

 private:
  HttpResponse Gate(const HttpRequest& req) const;
  HttpServer::NextChunk Events();

  std::string page_;
  AccessPolicy access_;
  HttpServer http_;
  FrameMailbox frames_;
  std::mutex mutex_;
  std::string scene_ = "null";
  int port_ = 0;
  std::thread thread_;
};

}  // namespace essaim
