// The Debug Adapter Protocol's base protocol: JSON messages, each after a
// "Content-Length: N\r\n\r\n" header, over a pair of file descriptors (stdin/stdout, or a
// TCP connection). Messages are core's value trees; JSON text through core/value_json.h.
#pragma once
#include <string>

#include "core/value.h"

namespace essaim {

class DapChannel {
 public:
  /// Reads from `in`, writes to `out` (the same socket, or stdin and a copy of stdout).
  DapChannel(int in, int out) : in_(in), out_(out) {}

  /// The next message, waiting up to `timeout_ms` (-1: forever). False on timeout (`closed`
  /// false) or when the client closed the connection or sent what is not DAP (`closed` true).
  bool Read(Value* message, int timeout_ms, bool* closed);
  /// Whether a whole message or more bytes are waiting (never blocks).
  bool Pending();
  /// Sends one message; its "seq" is set here. False once the client is gone.
  bool Send(Value message);
  bool Closed() const { return closed_; }
  /// For the copy that takes over after a going back: the socket it reads, the bytes read
  /// and not yet taken, the last seq sent.
  void Rebind(int fd) { in_ = out_ = fd; }
  const std::string& Unread() const { return buffer_; }
  void SetUnread(std::string bytes) { buffer_ = std::move(bytes); }
  long long Seq() const { return seq_; }
  void SetSeq(long long seq) { seq_ = seq; }

  /// A response to `request` (success, or failure with `message`).
  bool Respond(const Value& request, Value body, bool success = true, const std::string& message = "");
  bool Event(const std::string& event, Value body);
  /// An "output" event.
  bool Output(const std::string& category, const std::string& text);

 private:
  bool TakeMessage(Value* message, bool* bad);
  bool Fill(int timeout_ms);

  int in_, out_;
  std::string buffer_;
  long long seq_ = 0;
  bool closed_ = false;
};

/// The integer, string, bool, or object member of a message (defaults when missing).
long long IntField(const Value& v, const char* key, long long fallback = 0);
std::string StringField(const Value& v, const char* key, const std::string& fallback = "");
bool BoolField(const Value& v, const char* key, bool fallback = false);
const Value& ObjectField(const Value& v, const char* key);

/// Listens on 127.0.0.1:`port` and accepts one client; its socket, or -1 with `error`.
int AcceptOneClient(int port, std::string* error);

}  // namespace essaim
