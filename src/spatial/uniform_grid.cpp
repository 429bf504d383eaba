#include "spatial/uniform_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace essaim {

void UniformGrid::SetCells(const Vec2& origin, double cell, int columns, int rows) {
  origin_ = origin;
  cell_ = cell;
  inv_cell_ = 1 / cell;  // 0 for an infinite cell: every coordinate lands in cell 0
  columns_ = columns;
  rows_ = rows;
  cell_start_.assign(static_cast<size_t>(columns) * rows + 1, 0);
}

void UniformGrid::CoverBox(const Vec2& min, const Vec2& max, double cell, size_t max_cells) {
  const Vec2 extent = (max - min).cwiseMax(Vec2(1e-3, 1e-3));
  if (!(cell > 1e-3)) cell = 1e-3;  // also catches NaN
  cell = std::min(cell, std::max(extent.x(), extent.y()));
  max_cells = std::max<size_t>(max_cells, 1);
  if (!std::isfinite(extent.x()) || !std::isfinite(extent.y())) {  // a box near the double range's end
    SetCells(min, std::numeric_limits<double>::infinity(), 1, 1);
    return;
  }
  // Counted in double: a huge box over a small cell is past int's range until the cell grows.
  double columns = 1, rows = 1;
  for (;;) {
    columns = std::max(1.0, std::ceil(extent.x() / cell));
    rows = std::max(1.0, std::ceil(extent.y() / cell));
    if (columns * rows <= static_cast<double>(max_cells)) break;
    cell *= 1.5;
  }
  SetCells(min, cell, static_cast<int>(columns), static_cast<int>(rows));
}

void UniformGrid::CoverSpan(const Vec2& min, const Vec2& max, double cell, double max_cells) {
  // Room for the largest grid, so that a crowd spreading out or bunching up does not make
  // a later filing allocate.
  cell_start_.reserve(static_cast<size_t>(max_cells) + 1);
  const double w = max.x() - min.x(), h = max.y() - min.y();
  if (!std::isfinite(w) || !std::isfinite(h)) {  // items near the double range's end: one cell
    SetCells(min, std::numeric_limits<double>::infinity(), 1, 1);
    return;
  }
  while ((w / cell + 1) * (h / cell + 1) > max_cells) cell *= 2;
  const double inv_cell = 1 / cell;
  SetCells(min, cell, static_cast<int>(w * inv_cell) + 1, static_cast<int>(h * inv_cell) + 1);
}

void UniformGrid::Reserve(size_t entries, size_t items) {
  if (items_.size() < entries) items_.resize(entries);
  first_column_.reserve(items);
  first_row_.reserve(items);
}

size_t UniformGrid::DiscCells(double radius) const {
  const size_t span = static_cast<size_t>(std::ceil(2 * radius / cell_)) + 1;
  return std::min<size_t>(span, columns_) * std::min<size_t>(span, rows_);
}

}  // namespace essaim
