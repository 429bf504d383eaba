// Pictures of a recorded run: the replay page's top-down view drawn with Cairo, as a PNG
// (`essaim snapshot`, the Python module) or as raw pixels, frame after frame, for a video
// (`essaim video`). The only Cairo user; no Cairo type crosses this header.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

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

/// What a FrameRenderer draws besides the frame itself.
struct DrawOptions {
  /// The world rectangle the image shows (m): its min corner at the image's bottom-left.
  /// A zero size: the whole arena.
  Vec2 view_min = Vec2::Zero();
  Vec2 view_size = Vec2::Zero();
  bool tick = false;       // the tick and time, top left
  bool ids = false;        // each robot's id beside it
  bool scale_bar = false;  // a bar of a round length in metres, bottom left
};

/// Draws frames of one recording into one image of a fixed size, again and again: the floor
/// is decoded once, the image reused (a video's frames).
class FrameRenderer {
 public:
  FrameRenderer(const RecordingScene& scene, int width, int height);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  /// Draws `frames.back()`, each robot's trail through the frames before it (oldest first;
  /// one frame: no trail). False with `error` when Cairo fails.
  bool Draw(const std::vector<FrameView>& frames, const DrawOptions& options, std::string* error);
  int Width() const { return width_; }
  int Height() const { return height_; }
  /// The last image: Height() rows of Stride() bytes, top row first, 4 bytes a pixel in
  /// memory order B, G, R, unused on little-endian machines (Cairo's RGB24: native 0x00RRGGBB).
  const uint8_t* Pixels() const;
  int Stride() const;
  /// The last image as PNG bytes.
  bool Png(std::string* png, std::string* error) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  const RecordingScene& scene_;
  int width_, height_;
};

}  // namespace essaim
