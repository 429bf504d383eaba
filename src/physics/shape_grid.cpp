#include "physics/shape_grid.h"

#include <algorithm>
#include <cmath>

namespace essaim {

void ShapeGrid::Add(const GridCircle& c) {
  if (!std::isfinite(c.cx) || !std::isfinite(c.cy) || !std::isfinite(c.r)) return;
  circles_.push_back(c);
}

void ShapeGrid::Build() {
  nx_ = ny_ = 0;
  if (circles_.empty()) return;
  double lo_x = circles_[0].cx, hi_x = lo_x, lo_y = circles_[0].cy, hi_y = lo_y;
  for (const GridCircle& c : circles_) {
    lo_x = std::min(lo_x, c.cx - c.r);
    hi_x = std::max(hi_x, c.cx + c.r);
    lo_y = std::min(lo_y, c.cy - c.r);
    hi_y = std::max(hi_y, c.cy + c.r);
  }
  // A robot flung far away must not make the grid huge: past a few cells per shape, the
  // cells grow instead (queries get slower, never wrong).
  const double max_cells = std::max(4096.0, 4.0 * circles_.size());
  cell_ = kCellSize;
  const double w = hi_x - lo_x, h = hi_y - lo_y;
  x0_ = lo_x;
  y0_ = lo_y;
  if (!std::isfinite(w) || !std::isfinite(h)) {  // shapes near the double range's end: one cell
    inv_cell_ = 0;
    nx_ = ny_ = 1;
  } else {
    while ((w / cell_ + 1) * (h / cell_ + 1) > max_cells) cell_ *= 2;
    inv_cell_ = 1 / cell_;
    nx_ = static_cast<int>(w * inv_cell_) + 1;
    ny_ = static_cast<int>(h * inv_cell_) + 1;
  }

  // Counting sort into cells: count, running totals (each cell's end), then fill each cell
  // from its end, circles last to first, so cells keep filing order and end at their start.
  // Room for the largest grid and a foot-bot-sized circle in four cells each, so that a
  // crowd spreading out or bunching up does not make a later rebuild allocate.
  cell_start_.reserve(static_cast<size_t>(max_cells) + 1);
  filed_.reserve(4 * circles_.size());
  cell_start_.assign(static_cast<size_t>(nx_) * ny_ + 1, 0);
  for (GridCircle& c : circles_) {
    c.x0 = Column(c.cx - c.r);
    c.y0 = Row(c.cy - c.r);
    const int x1 = Column(c.cx + c.r), y1 = Row(c.cy + c.r);
    for (int row = c.y0; row <= y1; ++row)
      for (int col = c.x0; col <= x1; ++col) ++cell_start_[row * nx_ + col];
  }
  for (size_t k = 1; k < cell_start_.size(); ++k) cell_start_[k] += cell_start_[k - 1];
  filed_.resize(cell_start_.back());
  for (int i = static_cast<int>(circles_.size()) - 1; i >= 0; --i) {
    const GridCircle& c = circles_[i];
    const int x1 = Column(c.cx + c.r), y1 = Row(c.cy + c.r);
    for (int row = c.y0; row <= y1; ++row)
      for (int col = c.x0; col <= x1; ++col) filed_[--cell_start_[row * nx_ + col]] = i;
  }
}

}  // namespace essaim
