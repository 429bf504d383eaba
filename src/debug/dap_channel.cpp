#include "debug/dap_channel.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "core/fd_io.h"
#include "core/value_json.h"

namespace essaim {

namespace {
constexpr size_t kMaxMessage = 64u << 20;  // a client that sends more is not speaking DAP
}  // namespace

long long IntField(const Value& v, const char* key, long long fallback) {
  const Value* f = v.Find(key);
  if (!f) return fallback;
  if (f->kind == Value::Kind::Integer) return f->integer;
  if (f->kind == Value::Kind::Number) return static_cast<long long>(f->number);
  return fallback;
}

std::string StringField(const Value& v, const char* key, const std::string& fallback) {
  const Value* f = v.Find(key);
  return f && f->kind == Value::Kind::String ? f->text : fallback;
}

bool BoolField(const Value& v, const char* key, bool fallback) {
  const Value* f = v.Find(key);
  return f && f->kind == Value::Kind::Bool ? f->boolean : fallback;
}

const Value& ObjectField(const Value& v, const char* key) {
  static const Value empty = Value::EmptyMap();
  const Value* f = v.Find(key);
  return f ? *f : empty;
}

// A whole message at the front of the buffer, taken; `bad`: the header is not DAP's.
bool DapChannel::TakeMessage(Value* message, bool* bad) {
  const size_t end = buffer_.find("\r\n\r\n");
  if (end == std::string::npos) {
    *bad = buffer_.size() > 4096;
    return false;
  }
  size_t length = 0;
  bool found = false;
  for (size_t at = 0; at < end;) {
    size_t eol = buffer_.find("\r\n", at);
    if (eol == std::string::npos || eol > end) eol = end;
    const std::string line = buffer_.substr(at, eol - at);
    if (line.rfind("Content-Length:", 0) == 0) {
      length = std::strtoull(line.c_str() + 15, nullptr, 10);
      found = true;
    }
    at = eol + 2;
  }
  if (!found || length > kMaxMessage) {
    *bad = true;
    return false;
  }
  if (buffer_.size() < end + 4 + length) return false;
  const std::string body = buffer_.substr(end + 4, length);
  buffer_.erase(0, end + 4 + length);
  std::string error;
  if (!ParseJsonValue(body, message, &error) || message->kind != Value::Kind::Map) *message = Value::EmptyMap();
  return true;
}

// Reads what is there (waiting up to timeout_ms); false on timeout or end of input.
bool DapChannel::Fill(int timeout_ms) {
  pollfd p{in_, POLLIN, 0};
  int ready;
  do ready = poll(&p, 1, timeout_ms);
  while (ready < 0 && errno == EINTR);
  if (ready <= 0) return false;
  char chunk[65536];
  ssize_t n;
  do n = read(in_, chunk, sizeof chunk);
  while (n < 0 && errno == EINTR);
  if (n <= 0) {
    closed_ = true;
    return false;
  }
  buffer_.append(chunk, static_cast<size_t>(n));
  return true;
}

bool DapChannel::Read(Value* message, int timeout_ms, bool* closed) {
  *closed = false;
  while (true) {
    bool bad = false;
    if (TakeMessage(message, &bad)) return true;
    if (bad) closed_ = true;
    if (closed_) {
      *closed = true;
      return false;
    }
    if (!Fill(timeout_ms)) {
      *closed = closed_;
      return false;
    }
  }
}

bool DapChannel::Pending() {
  if (buffer_.find("\r\n\r\n") != std::string::npos) return true;
  pollfd p{in_, POLLIN, 0};
  return !closed_ && poll(&p, 1, 0) > 0;
}

bool DapChannel::Send(Value message) {
  if (closed_) return false;
  message.Set("seq", Value::OfInteger(++seq_));
  const std::string body = ValueJsonLine(message);
  const std::string text = "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
  if (!WriteAll(out_, text.data(), text.size())) closed_ = true;
  return !closed_;
}

bool DapChannel::Respond(const Value& request, Value body, bool success, const std::string& message) {
  Value r = Value::EmptyMap();
  r.Set("type", Value::OfString("response"));
  r.Set("request_seq", Value::OfInteger(IntField(request, "seq")));
  r.Set("success", Value::OfBool(success));
  r.Set("command", Value::OfString(StringField(request, "command")));
  if (!success) r.Set("message", Value::OfString(message));
  if (!body.IsNull()) r.Set("body", std::move(body));
  return Send(std::move(r));
}

bool DapChannel::Event(const std::string& event, Value body) {
  Value e = Value::EmptyMap();
  e.Set("type", Value::OfString("event"));
  e.Set("event", Value::OfString(event));
  if (!body.IsNull()) e.Set("body", std::move(body));
  return Send(std::move(e));
}

bool DapChannel::Output(const std::string& category, const std::string& text) {
  return Event("output", Value::MapOf({{"category", Value::OfString(category)}, {"output", Value::OfString(text)}}));
}

int AcceptOneClient(int port, std::string* error) {
  const int listener = socket(AF_INET, SOCK_STREAM, 0);
  int one = 1;
  setsockopt(listener, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (listener < 0 || bind(listener, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 ||
      listen(listener, 1) != 0) {
    *error = "--port " + std::to_string(port) + ": " + std::strerror(errno);
    if (listener >= 0) close(listener);
    return -1;
  }
  int client;
  do client = accept(listener, nullptr, nullptr);
  while (client < 0 && errno == EINTR);
  if (client < 0) *error = std::string("--port: accept: ") + std::strerror(errno);
  close(listener);
  return client;
}

}  // namespace essaim
