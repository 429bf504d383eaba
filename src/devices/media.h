// Media state rebuilt after physics each tick: who hears whom (range and bearing), where
// lit LEDs are (cameras). Read-only during sensing.
#pragma once
#include <vector>

#include "devices/robot_state.h"
#include "model/model.h"
#include "physics/physics_world.h"

namespace essaim {

struct Media {
  /// rab_inbox[r] = senders whose packet robot r receives this tick, ascending index.
  std::vector<std::vector<int>> rab_inbox;
};

/// Media stage: rebuilds routing from the robots' positions after physics.
void UpdateMedia(const Model& model, const PhysicsWorld& physics, const std::vector<RobotState>& robots, Media* media);

}  // namespace essaim
