// Inside the ARGoS API library: what one session holds, and the session whose hook is
// running now (CSimulator::GetInstance's answer).
#pragma once
#include <argos3/core/simulator/loop_functions.h>
#include <argos3/core/utility/math/rng.h>
#include <argos3/plugins/simulator/media/led_medium.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "argos/argos_session.h"

namespace argos {
/// Makes the one CSimulator of a session (its constructor is private, as ARGoS's singleton's).
struct SSessionAccess {
  static CSimulator Make() { return CSimulator(); }
};
}  // namespace argos

namespace essaim {

/// A CRandom category other than "argos": ARGoS's CCategory, a seeder whose draws seed its
/// generators.
struct ArgosRngCategory {
  explicit ArgosRngCategory(argos::UInt32 un_seed) : seed(un_seed), seeder(un_seed) {}
  argos::UInt32 seed;
  argos::CRandom::CRNG seeder;
  std::vector<std::unique_ptr<argos::CRandom::CRNG>> rngs;  // category "argos"
  std::map<std::string, ArgosRngCategory> rng_categories;   // the others
};

struct ArgosSession::State {
  explicit State(ArgosWorld* w) : world(w), simulator(argos::SSessionAccess::Make()) {}
  ArgosWorld* world;
  argos::CSimulator simulator;
  argos::CSpace space;
  std::map<std::string, std::unique_ptr<argos::CLEDMedium>> media;
  std::vector<std::unique_ptr<argos::CRandom::CRNG>> rngs;  // category "argos"
  std::map<std::string, ArgosRngCategory> rng_categories;   // the others
  std::unique_ptr<argos::CLoopFunctions> loop_functions;
  bool configuration_error = false;  // the last hook's exception was a bad .argos element
};

/// The session whose hook runs on this thread; null outside hooks.
ArgosSession::State* CurrentSession();
/// The current session; throws a CARGoSException naming `what` when there is none.
ArgosSession::State& RequireSession(const char* what);

}  // namespace essaim
