// The floor as a raster over the arena: from an image (stretched, bottom-left pixel at
// the arena's min corner) or sampled once from the loop functions'
// floor_color(x, y). Ground sensors read it.
#pragma once
#include <algorithm>
#include <vector>

#include "core/math.h"

namespace essaim {

struct FloorRaster {
  int width = 0, height = 0;
  std::vector<Color> pixels;  // bottom row first
  Vec2 min = Vec2::Zero();    // arena min corner (m)
  Vec2 size = Vec2::Ones();   // arena size (m)

  bool Empty() const { return pixels.empty(); }
  /// Colour under (x, y). Outside the arena reads the nearest edge pixel (ARGoS aborts the
  /// run instead; docs/compatibility.md).
  Color At(double x, double y) const {
    if (pixels.empty()) return Color{255, 255, 255, 255};
    int px = Cell((x - min.x()) * width / size.x(), width);
    int py = Cell((y - min.y()) * height / size.y(), height);
    return pixels[static_cast<size_t>(py) * width + px];
  }
  /// The cell holding raster coordinate `v` of `n` cells; clamped before the int cast, so
  /// that a robot 1e48 m away (or NaN) reads an edge cell instead of overflowing the cast
  /// (UBSan, found by fuzz_argos).
  static int Cell(double v, int n) {
    if (!(v >= 0)) return 0;
    if (v >= n - 1) return n - 1;
    return static_cast<int>(v);
  }
  /// Grey level in [0, 1]: (0.299 R + 0.587 G + 0.114 B) / 255.
  double Grey(double x, double y) const {
    Color c = At(x, y);
    return (0.299 * c.r + 0.587 * c.g + 0.114 * c.b) / 255.0;
  }
};

}  // namespace essaim
