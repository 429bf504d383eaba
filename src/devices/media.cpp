#include "devices/media.h"

namespace essaim {

void UpdateMedia(const Model&, const PhysicsWorld&, const std::vector<RobotState>&, Media* media) {
  // Range-and-bearing routing is added with the RAB devices; until then nobody hears anyone.
  for (auto& inbox : media->rab_inbox) inbox.clear();
}

}  // namespace essaim
