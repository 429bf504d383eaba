#include "serve/access.h"

#include <algorithm>
#include <random>

namespace essaim {

std::string NewToken() {
  std::random_device device;  // the kernel's random source on Linux
  static const char kHex[] = "0123456789abcdef";
  std::string token;
  for (int i = 0; i < 4; ++i) {
    uint32_t v = device();
    for (int k = 0; k < 8; ++k, v >>= 4) token += kHex[v & 15];
  }
  return token;
}

std::vector<std::string> OwnHosts(const std::string& bind_host, int port) {
  const std::string p = ":" + std::to_string(port);
  std::vector<std::string> hosts = {"127.0.0.1" + p, "localhost" + p, "[::1]" + p};
  std::string bound = bind_host.find(':') != std::string::npos ? "[" + bind_host + "]" : bind_host;
  if (std::find(hosts.begin(), hosts.end(), bound + p) == hosts.end()) hosts.push_back(bound + p);
  return hosts;
}

namespace {
// Compares in time independent of where the strings first differ.
bool SameSecret(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  unsigned char diff = 0;
  for (size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

bool IsOwnHost(const AccessPolicy& policy, const std::string& host) {
  return std::find(policy.hosts.begin(), policy.hosts.end(), host) != policy.hosts.end();
}
}  // namespace

int CheckAccess(const AccessPolicy& policy, const std::string& host, const std::string& origin,
                const std::string& query_token, const std::string& authorization, std::string* why) {
  if (!IsOwnHost(policy, host)) {
    *why = "Host '" + host + "' is not this server";
    return 403;
  }
  if (!origin.empty() && !(origin.rfind("http://", 0) == 0 && IsOwnHost(policy, origin.substr(7)))) {
    *why = "Origin '" + origin + "' is not this server";
    return 403;
  }
  std::string token = query_token;
  const std::string bearer = "Bearer ";
  if (authorization.rfind(bearer, 0) == 0) token = authorization.substr(bearer.size());
  if (token.empty()) {
    *why = "a token is needed: ?token=T or Authorization: Bearer T (printed when the server started)";
    return 401;
  }
  if (!SameSecret(token, policy.token)) {
    *why = "wrong token";
    return 403;
  }
  return 0;
}

}  // namespace essaim
