// The HTTP server of `essaim serve`: the only cpp-httplib user. Handlers see plain
// requests and give plain answers; an event stream (server-sent events) is a function
// that gives the next chunk to send, on the connection's own thread.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>

namespace essaim {

struct HttpRequest {
  std::string method, path, body;
  std::map<std::string, std::string> params;  // the query string's, decoded
  std::string host, origin, authorization;    // headers ("" when not sent)
  std::string Param(const std::string& name) const {
    auto it = params.find(name);
    return it == params.end() ? std::string() : it->second;
  }
};

struct HttpResponse {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
};

class HttpServer {
 public:
  using Handler = std::function<HttpResponse(const HttpRequest&)>;
  /// Gives the next chunk of an event stream, waiting as long as it needs; false ends the
  /// stream. Writing a chunk to a client that left ends it too.
  using NextChunk = std::function<bool(std::string* chunk)>;
  using Stream = std::function<NextChunk(const HttpRequest&)>;

  HttpServer();
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  /// Runs before every route: an answer with status 0 lets the request through, any other
  /// is sent as it is (access control).
  void SetGate(Handler gate);
  void Get(const std::string& path, Handler handler);
  void Post(const std::string& path, Handler handler);
  void EventStream(const std::string& path, Stream stream);
  /// Binds `host`:`port` (0: a free port); false with `error`. *bound is the port.
  bool Bind(const std::string& host, int port, int* bound, std::string* error);
  /// Serves until Stop() (from any thread).
  void Run();
  void Stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace essaim
