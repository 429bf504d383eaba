#include "serve/http_server.h"

#include <httplib.h>

namespace essaim {

struct HttpServer::Impl {
  httplib::Server server;
  Handler gate;
};

namespace {
HttpRequest Convert(const httplib::Request& r) {
  HttpRequest out;
  out.method = r.method;
  out.path = r.path;
  out.body = r.body;
  for (const auto& [name, value] : r.params) out.params.emplace(name, value);
  out.host = r.get_header_value("Host");
  out.origin = r.get_header_value("Origin");
  out.authorization = r.get_header_value("Authorization");
  return out;
}

void Send(const HttpResponse& answer, httplib::Response* res) {
  res->status = answer.status;
  res->set_header("Cache-Control", "no-store");
  res->set_header("Referrer-Policy", "no-referrer");  // the page's address holds the token
  res->set_content(answer.body, answer.content_type);
}

httplib::Server::Handler Wrap(HttpServer::Handler handler) {
  return [handler](const httplib::Request& req, httplib::Response& res) { Send(handler(Convert(req)), &res); };
}
}  // namespace

HttpServer::HttpServer() : impl_(std::make_unique<Impl>()) {
  impl_->server.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    if (!impl_->gate) return httplib::Server::HandlerResponse::Unhandled;
    HttpResponse answer = impl_->gate(Convert(req));
    if (answer.status == 0) return httplib::Server::HandlerResponse::Unhandled;
    Send(answer, &res);
    return httplib::Server::HandlerResponse::Handled;
  });
  impl_->server.set_payload_max_length(1 << 20);  // control commands are small
  // Each open page holds a worker for its event stream, and browsers keep connections
  // open: more workers than the default 8, so a few pages never starve the API.
  impl_->server.new_task_queue = [] { return new httplib::ThreadPool(32); };
}

HttpServer::~HttpServer() { Stop(); }

void HttpServer::SetGate(Handler gate) { impl_->gate = std::move(gate); }

void HttpServer::Get(const std::string& path, Handler handler) { impl_->server.Get(path, Wrap(std::move(handler))); }

void HttpServer::Post(const std::string& path, Handler handler) { impl_->server.Post(path, Wrap(std::move(handler))); }

void HttpServer::EventStream(const std::string& path, Stream stream) {
  impl_->server.Get(path, [stream](const httplib::Request& req, httplib::Response& res) {
    NextChunk next = stream(Convert(req));
    res.set_header("Cache-Control", "no-store");
    res.set_chunked_content_provider("text/event-stream", [next](size_t, httplib::DataSink& sink) {
      std::string chunk;
      if (!next(&chunk)) {
        sink.done();
        return true;
      }
      return sink.write(chunk.data(), chunk.size());  // false once the client has gone
    });
  });
}

bool HttpServer::Bind(const std::string& host, int port, int* bound, std::string* error) {
  if (port == 0) {
    *bound = impl_->server.bind_to_any_port(host);
    if (*bound > 0) return true;
  } else if (impl_->server.bind_to_port(host, port)) {
    *bound = port;
    return true;
  }
  *error = "cannot listen on " + host + ":" + std::to_string(port) + " (in use, or not an address of this machine)";
  return false;
}

void HttpServer::Run() { impl_->server.listen_after_bind(); }

void HttpServer::Stop() {
  if (impl_->server.is_running()) impl_->server.stop();
}

}  // namespace essaim
