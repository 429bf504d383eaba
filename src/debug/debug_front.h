// The process the editor started, once the run begins: it owns the client's connection
// and never simulates. It relays the protocol's bytes between the client and whichever
// process is the live simulation now (they share one socket; a going back hands it on),
// and ends with the exit code the last live simulation reports.
#pragma once
#include <sys/types.h>

namespace essaim {

/// The sockets and pipe between the front and the simulations.
struct FrontLink {
  int sim_socket = -1;  // the simulations' end of the protocol's socketpair
  int status_fd = -1;   // the simulations' end of the exit-code pipe
};

/// Forks the simulation. In the front: relays until the simulation reports its exit
/// code, ends every simulation process (checkpoints included) and returns that code (>= 0).
/// In the simulation: returns -1 with `link` set (the client's descriptors closed there).
int StartFront(int client_in, int client_out, FrontLink* link);

/// A copy woken from a checkpoint tells the front it is the live simulation now (the front
/// ends the session, exit 3, when the live one is gone without an exit code: a crash).
void TellFrontLive(const FrontLink& link);

/// The live simulation's last act: its exit code to the front, then _exit.
[[noreturn]] void EndSimulation(const FrontLink& link, int code);

}  // namespace essaim
