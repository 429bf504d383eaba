// Who may talk to `essaim serve`: the token printed at start, and only pages of the
// server's own origin (a page elsewhere must not drive or read the simulator: CSRF, DNS
// rebinding). Plain functions of the request's fields, so they are tested without a socket.
#pragma once
#include <string>
#include <vector>

namespace essaim {

/// 32 hex digits from the system's random source: a fresh token each start.
std::string NewToken();

struct AccessPolicy {
  std::string token;
  /// Host header values that name this server ("127.0.0.1:8080", "localhost:8080", ...).
  std::vector<std::string> hosts;
  /// Listening on every address (0.0.0.0, ::): any IP address with this port names the
  /// server too. Names other than localhost never do (DNS rebinding uses names).
  bool any_address = false;
  int port = 0;
};

/// The policy of a server bound to `bind_host`:`port` with this token.
AccessPolicy PolicyFor(const std::string& token, const std::string& bind_host, int port);

/// The Host values a server bound to `bind_host`:`port` answers to: loopback names always,
/// the bound address when it is another one.
std::vector<std::string> OwnHosts(const std::string& bind_host, int port);

/// 0 when the request may go on; else 403 (a foreign Host or Origin, a wrong token) or 401
/// (no token), with the reason in `why`. `query_token` is ?token=, `authorization` the
/// Authorization header ("Bearer T"); `origin` may be empty (not sent).
int CheckAccess(const AccessPolicy& policy, const std::string& host, const std::string& origin,
                const std::string& query_token, const std::string& authorization, std::string* why);

}  // namespace essaim
