// Snapshots of a recorded run: the replay page's top-down view drawn with Cairo into a PNG
// (`essaim snapshot`). The only Cairo user; no Cairo type crosses this header.
#pragma once
#include <cstddef>
#include <string>

#include "output/recording.h"

namespace essaim {

struct SnapshotOptions {
  int size = 1024;      // px of the image's longer side; the arena fills the image
  int trail_ticks = 0;  // draw each robot's path over the last N ticks (0: none)
  bool labels = false;  // the tick (top left) and each robot's id beside it
};

/// Image size for an arena: the longer side is `size` px, the other keeps the aspect ratio.
void SnapshotImageSize(const RecordingScene& scene, int size, int* width, int* height);

/// Draws frame `frame` of `rec` as PNG bytes into `png` (the arena's min corner at the image's
/// bottom-left, +y up). False with `error` when Cairo fails.
bool RenderSnapshotPng(const Recording& rec, size_t frame, const SnapshotOptions& options, std::string* png,
                       std::string* error);

}  // namespace essaim
