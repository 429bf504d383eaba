// Inside the ARGoS API library: what one session holds, and the session whose hook is
// running now (CSimulator::GetInstance's answer).
#pragma once
#include <argos3/core/control_interface/ci_controller.h>
#include <argos3/core/simulator/actuator.h>
#include <argos3/core/simulator/loop_functions.h>
#include <argos3/core/simulator/sensor.h>
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

/// A CRandom category: ARGoS's CCategory, a seeder whose draws seed its generators.
struct ArgosRngCategory {
  explicit ArgosRngCategory(argos::UInt32 un_seed) : seed(un_seed), seeder(un_seed) {}
  argos::UInt32 seed;
  argos::CRandom::CRNG seeder;
  std::vector<std::unique_ptr<argos::CRandom::CRNG>> rngs;
};

/// One robot's C++ controller with the sensor and actuator objects made for it, and what
/// belongs to it alone, so that different robots' steps share nothing.
struct ArgosControllerSlot {
  uint32_t robot = 0;
  std::string robot_id, config_id, where;
  std::unique_ptr<argos::CCI_Controller> controller;
  std::vector<std::unique_ptr<argos::CSimulatedSensor>> sensors;
  std::vector<std::unique_ptr<argos::CSimulatedActuator>> actuators;
  std::string log;  // "<O or E><text>\n" each, emptied by the host
  /// Generators made during ControlStep, and the robot's own seeder per category that
  /// seeds them (rng.cpp: never the category's shared one, which other threads could draw).
  std::map<std::string, argos::CRandom::CRNG> step_seeders;
  std::vector<std::unique_ptr<argos::CRandom::CRNG>> step_rngs;
};

/// The controller call running on this thread: where its LOG lines go; `parallel` while
/// other robots' steps may run at once.
struct ArgosControllerCall {
  ArgosControllerSlot* slot = nullptr;
  bool parallel = false;
};

struct ArgosSession::State {
  explicit State(ArgosWorld* w) : world(w), simulator(argos::SSessionAccess::Make()) {}
  ArgosWorld* world;
  argos::CSimulator simulator;
  argos::CSpace space;
  std::map<std::string, std::unique_ptr<argos::CLEDMedium>> media;
  std::map<std::string, ArgosRngCategory> rng_categories;  // "argos" made with the session
  std::unique_ptr<argos::CLoopFunctions> loop_functions;
  /// By robot index; grown only by CreateController (serial), read by parallel steps.
  std::vector<std::unique_ptr<ArgosControllerSlot>> controllers;
  std::string no_log;  // ControllerLog of a robot without a controller
  argos::CPhysicsEngine physics{"physics"};
  argos::CPhysicsEngine::TVector physics_engines{&physics};
  bool configuration_error = false;  // the last hook's exception was a bad .argos element
};

/// The session whose hook runs on this thread; null outside hooks.
ArgosSession::State* CurrentSession();
/// Makes `state` the current session of this thread; the one it was before.
ArgosSession::State* SetCurrentSession(ArgosSession::State* state);
/// "FILE:LINE: message" (the message alone when it has no file).
std::string DescribeException(const argos::CARGoSException& e);
/// The controller call running on this thread; null outside one.
const ArgosControllerCall* CurrentControllerCall();
/// Robot `robot`'s C++ controller in the current session; null when it has none.
argos::CCI_Controller* CurrentController(uint32_t robot);
/// The current session; throws a CARGoSException naming `what` when there is none.
ArgosSession::State& RequireSession(const char* what);

}  // namespace essaim
