// Foot-bots that loop functions add during a run (C++ AddEntity, Lua add_entity): the
// EntityStore adds the body and state, and this joiner gives the robot what World
// creation gives each robot of the .argos file: a Lua state with its script run, init()
// called, a slot in the per-robot buffers. As in ARGoS, where a CFootBotEntity made by
// loop functions runs its controller's Init() before AddEntity returns.
#pragma once
#include <string>

#include "devices/entity_store.h"

namespace essaim {

class World;

class WorldRobotJoiner : public RobotJoiner {
 public:
  explicit WorldRobotJoiner(World& world) : world_(world) {}
  /// False (the robot taken back out) when its script fails to load, when init() leaves
  /// no step(), or when init() fails a run that stops at the first error (--strict,
  /// os.exit). Another init() error stops only this robot, reported as at the start.
  bool Join(int index, std::string* error) override;

 private:
  World& world_;
};

}  // namespace essaim
