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

#include "core/fd_io.h"

namespace essaim {

namespace {
bool Forward(int from, int to) {
  char chunk[65536];
  ssize_t n;
  do n = read(from, chunk, sizeof chunk);
  while (n < 0 && errno == EINTR);
  if (n <= 0) return false;
  WriteAll(to, chunk, static_cast<size_t>(n));  // the client gone: the simulation learns it from the socket
  return true;
}

// What a simulation tells the front on the status pipe.
struct Status {
  int kind;  // kLive: `value` is the live simulation's pid; kExit: its exit code
  int value;
};
constexpr int kLive = 1, kExit = 0;

// Whether `pid` still runs (the first simulation is the front's child: reaped here).
bool Running(pid_t pid, pid_t child) {
  if (pid == child) return waitpid(child, nullptr, WNOHANG) == 0;
  return kill(pid, 0) == 0;
}

// Relays until the exit code comes (then what the simulation sent before it is passed on),
// or until the live simulation is gone without one (it crashed: exit 3).
int Relay(int client_in, int client_out, int sim, int status, pid_t child, FrontSide& side) {
  bool client_open = true;
  pid_t live = child;
  int gone = 0;  // seconds the live simulation has been gone (a going back hands over in ms)
  auto drain = [&side] {
    if (side.fd >= 0 && !side.drain()) side.fd = -1;
  };
  while (true) {
    pollfd p[4] = {
        {sim, POLLIN, 0}, {status, POLLIN, 0}, {client_open ? client_in : -1, POLLIN, 0}, {side.fd, POLLIN, 0}};
    const int ready = poll(p, 4, 1000);
    if (ready < 0 && errno != EINTR) return 1;
    if (ready == 0 && !Running(live, child) && ++gone >= 3) return 3;
    if (p[3].revents & (POLLIN | POLLHUP)) drain();
    if (p[0].revents & (POLLIN | POLLHUP)) {
      drain();
      Forward(sim, client_out);
    }
    if (p[2].revents & (POLLIN | POLLHUP) && !Forward(client_in, sim)) {
      client_open = false;
      shutdown(sim, SHUT_WR);  // the simulation reads the end of input: the client left
    }
    if (!(p[1].revents & (POLLIN | POLLHUP))) continue;
    Status s{kExit, 1};
    if (read(status, &s, sizeof s) != sizeof s) s = {kExit, 1};
    if (s.kind == kLive) {
      live = s.value;
      gone = 0;
      continue;
    }
    drain();
    fcntl(sim, F_SETFL, O_NONBLOCK);
    while (Forward(sim, client_out)) {
    }
    return s.value;
  }
}
}  // namespace

int StartFront(int client_in, int client_out, FrontLink* link, FrontSide side) {
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
  if (side.start) side.start();
  const int code = Relay(client_in, client_out, sv[0], status[0], sim, side);
  kill(-sim, SIGKILL);
  waitpid(sim, nullptr, 0);
  return code;
}

void TellFrontLive(const FrontLink& link) {
  const Status s{kLive, static_cast<int>(getpid())};
  if (write(link.status_fd, &s, sizeof s) != sizeof s) return;  // the front is gone: nobody to tell
}

void EndSimulation(const FrontLink& link, int code) {
  std::fflush(stdout);
  std::fflush(stderr);
  const Status s{kExit, code};
  if (write(link.status_fd, &s, sizeof s) != sizeof s) _exit(code);
  _exit(code);
}

}  // namespace essaim
