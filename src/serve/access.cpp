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

AccessPolicy PolicyFor(const std::string& token, const std::string& bind_host, int port) {
  AccessPolicy p;
  p.token = token;
  p.hosts = OwnHosts(bind_host, port);
  p.any_address = bind_host == "0.0.0.0" || bind_host == "::";
  p.port = port;
  return p;
}

namespace {
// Compares in time independent of where the strings first differ.
bool SameSecret(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  unsigned char diff = 0;
  for (size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

// "1.2.3.4:PORT" or "[v6]:PORT" with the server's port.
bool IsAddressWithPort(const std::string& host, int port) {
  const std::string suffix = ":" + std::to_string(port);
  if (host.size() <= suffix.size() || host.compare(host.size() - suffix.size(), suffix.size(), suffix) != 0)
    return false;
  std::string address = host.substr(0, host.size() - suffix.size());
  if (address.size() > 2 && address.front() == '[' && address.back() == ']')
    return address.find_first_not_of("0123456789abcdefABCDEF:.", 1) == address.size() - 1;
  int dots = 0;
  for (char c : address) {
    if (c == '.')
      ++dots;
    else if (c < '0' || c > '9')
      return false;
  }
  return dots == 3;
}

bool IsOwnHost(const AccessPolicy& policy, const std::string& host) {
  if (std::find(policy.hosts.begin(), policy.hosts.end(), host) != policy.hosts.end()) return true;
  return policy.any_address && IsAddressWithPort(host, policy.port);
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
