#include "serve/view_server.h"

#include <chrono>

#include "core/value_json.h"

namespace essaim {

namespace {
using Clock = std::chrono::steady_clock;
constexpr auto kFrameInterval = std::chrono::milliseconds(33);  // at most 30 frames per second per page
}  // namespace

ViewServer::ViewServer(std::string page) : page_(std::move(page)) {}

ViewServer::~ViewServer() { Stop(); }

void ViewServer::SetScene(std::string scene_json) {
  std::lock_guard<std::mutex> lock(mutex_);
  scene_ = std::move(scene_json);
}

HttpResponse ViewServer::Gate(const HttpRequest& req) const {
  if (req.path == "/favicon.ico") return {204, "image/x-icon", ""};  // browsers ask, without the token
  std::string why;
  int status = CheckAccess(access_, req.host, req.origin, req.Param("token"), req.authorization, &why);
  if (status == 0) return {0, "", ""};
  return {status, "application/json", ValueJsonLine(Value::MapOf({{"error", Value::OfString(why)}}))};
}

HttpServer::NextChunk ViewServer::Events() {
  struct Client {
    uint64_t seq = 0;
    Clock::time_point last_sent;
  };
  auto client = std::make_shared<Client>();
  return [this, client](std::string* chunk) {
    // At most one frame per interval per client; the latest one when it is time.
    auto next = client->last_sent + kFrameInterval;
    if (Clock::now() < next) std::this_thread::sleep_until(next);
    FrameMailbox::Frame frame;
    if (!frames_.WaitNewer(&client->seq, &frame, std::chrono::seconds(10))) {
      if (frames_.Closed()) return false;
      *chunk = ": still here\n\n";  // a comment: finds clients that left
      return true;
    }
    client->last_sent = Clock::now();
    *chunk = SseEvent("frame", *frame);
    return true;
  };
}

bool ViewServer::Start(const std::string& host, int port, const std::string& token, std::string* error) {
  http_.SetGate([this](const HttpRequest& req) { return Gate(req); });
  http_.Get("/", [this](const HttpRequest&) { return HttpResponse{200, "text/html; charset=utf-8", page_}; });
  http_.Get("/api/state", [this](const HttpRequest&) {
    FrameMailbox::Frame f = frames_.Latest();
    return HttpResponse{200, "application/json", f ? *f : "null"};
  });
  http_.Get("/api/scene", [this](const HttpRequest&) {
    std::lock_guard<std::mutex> lock(mutex_);
    return HttpResponse{200, "application/json", scene_};
  });
  http_.EventStream("/api/events", [this](const HttpRequest&) { return Events(); });
  if (!http_.Bind(host, port, &port_, error)) return false;
  access_ = PolicyFor(token.empty() ? NewToken() : token, host, port_);
  thread_ = std::thread([this] { http_.Run(); });
  return true;
}

std::string ViewServer::Url(const std::string& host) const {
  std::string shown = host == "0.0.0.0" || host == "::"     ? "127.0.0.1"
                      : host.find(':') != std::string::npos ? "[" + host + "]"
                                                            : host;
  return "http://" + shown + ":" + std::to_string(port_) + "/?token=" + access_.token;
}

void ViewServer::Stop() {
  frames_.Close();
  http_.Stop();
  if (thread_.joinable()) thread_.join();
}

}  // namespace essaim
