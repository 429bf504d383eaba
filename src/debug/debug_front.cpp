#include "debug/debug_front.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

namespace essaim {

namespace {
bool Forward(int from, int to) {
  char chunk[65536];
  ssize_t n;
  do n = read(from, chunk, sizeof chunk);
  while (n < 0 && errno == EINTR);
  if (n <= 0) return false;
  for (ssize_t done = 0; done < n;) {
    const ssize_t w = write(to, chunk + done, static_cast<size_t>(n - done));
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return true;  // the client is gone; the simulation learns it from the socket
    done += w;
  }
  return true;
}

// Relays until the exit code comes; then what the simulation sent before it is passed on.
int Relay(int client_in, int client_out, int sim, int status) {
  bool client_open = true;
  while (true) {
    pollfd p[3] = {{sim, POLLIN, 0}, {status, POLLIN, 0}, {client_open ? client_in : -1, POLLIN, 0}};
    if (poll(p, 3, -1) < 0 && errno != EINTR) return 1;
    if (p[0].revents & (POLLIN | POLLHUP)) Forward(sim, client_out);
    if (p[2].revents & (POLLIN | POLLHUP) && !Forward(client_in, sim)) {
      client_open = false;
      shutdown(sim, SHUT_WR);  // the simulation reads the end of input: the client left
    }
    if (p[1].revents & (POLLIN | POLLHUP)) {
      int code = 1;
      if (read(status, &code, sizeof code) != sizeof code) code = 1;
      fcntl(sim, F_SETFL, O_NONBLOCK);
      while (Forward(sim, client_out)) {
      }
      return code;
    }
  }
}
}  // namespace

int StartFront(int client_in, int client_out, FrontLink* link) {
  int sv[2], status[2];
  if (socketpair(AF_UNIX, SOCK_STREAM, 0, sv) != 0 || pipe(status) != 0) return -1;
  const pid_t front = getpid();
  const pid_t sim = fork();
  if (sim == 0) {
    setpgid(0, 0);  // the simulation and its checkpoints: one group, ended together
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != front) _exit(1);
    signal(SIGCHLD, SIG_IGN);  // checkpoints and their copies are never waited for
    close(sv[0]);
    close(status[0]);
    close(client_in);
    if (client_out != client_in) close(client_out);
    link->sim_socket = sv[1];
    link->status_fd = status[1];
    return -1;
  }
  close(sv[1]);
  close(status[1]);
  if (sim < 0) {
    std::fprintf(stderr, "essaim debug: cannot start the simulation process\n");
    return 1;
  }
  setpgid(sim, sim);
  signal(SIGPIPE, SIG_IGN);
  const int code = Relay(client_in, client_out, sv[0], status[0]);
  kill(-sim, SIGKILL);
  waitpid(sim, nullptr, 0);
  return code;
}

void EndSimulation(const FrontLink& link, int code) {
  std::fflush(stdout);
  std::fflush(stderr);
  if (write(link.status_fd, &code, sizeof code) != sizeof code) _exit(code);
  _exit(code);
}

}  // namespace essaim
