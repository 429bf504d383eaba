// The floor as a raster over the arena: from an image (stretched, bottom-left pixel at
// the arena's min corner, spec §4.3) or sampled once from the loop functions'
// floor_color(x, y). Ground sensors read it.
#pragma once
#include <algorithm>
#include <vector>

#include "core/math.h"

namespace essaim {

struct FloorRaster {
  int width = 0, height = 0;
  std::vector<Color> pixels;   // bottom row first
  Vec2 min = Vec2::Zero();     // arena min corner (m)
  Vec2 size = Vec2::Ones();    // arena size (m)

  bool Empty() const { return pixels.empty(); }
  /// Colour under (x, y). Outside the arena reads the nearest edge pixel (ARGoS aborts the
  /// run instead; docs/compatibility.md).
  Color At(double x, double y) const {
    if (pixels.empty()) return Color{255, 255, 255, 255};
    int px = static_cast<int>((x - min.x()) * width / size.x());
    int py = static_cast<int>((y - min.y()) * height / size.y());
    px = std::clamp(px, 0, width - 1);
    py = std::clamp(py, 0, height - 1);
    return pixels[static_cast<size_t>(py) * width + px];
  }
  /// Grey level in [0, 1]: (0.299 R + 0.587 G + 0.114 B) / 255.
  double Grey(double x, double y) const {
    Color c = At(x, y);
    return (0.299 * c.r + 0.587 * c.g + 0.114 * c.b) / 255.0;
  }
};

}  // namespace essaim
