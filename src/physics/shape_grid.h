// A uniform grid over the bounding circles of every shape, rebuilt whole when the shapes
// have moved: a robot's ray candidates come from the few cells round its sensing disc
// instead of a walk down Box2D's tree (issue 12: at foraging-300 that walk was most of the
// cost of gathering a scanner's candidates, at avoidance-1000 most of the proximity ring's).
// Plain data, no Box2D: the physics world fills it.
#pragma once
#include <vector>

namespace essaim {

/// One shape as the grid files it.
struct GridCircle {
  double cx = 0, cy = 0, r = 0;  // m, a circle containing the shape
  double bottom = 0, top = 0;    // m, the shape's vertical extent
  int robot = -1;                // robot index, -1 for obstacles
  const void* shape = nullptr;   // the caller's handle (a b2Fixture*)
  int x0 = 0, y0 = 0;            // first cell column and row it is filed in (set by Build)
};

class ShapeGrid {
 public:
  /// Forgets every circle (capacity kept: rebuilding allocates nothing once warm).
  void Clear() { circles_.clear(); }
  /// Files `c` at the next Build. Circles with a non-finite centre or radius are dropped:
  /// no ray can hit them either.
  void Add(const GridCircle& c);
  /// Files every added circle in each cell its bounding box overlaps.
  void Build();
  /// Calls f(circle) once for every circle filed in a cell that the square of half-side
  /// `radius` round (x, y) overlaps: all circles that can touch that disc, and some others.
  /// In filing order within a cell, cells row by row: deterministic.
  template <class F>
  void ForEachNear(double x, double y, double radius, F&& f) const {
    ForEachInBox(x - radius, y - radius, x + radius, y + radius, f);
  }
  /// Calls f(circle) once for every circle filed in a cell that the box [x0, x1] × [y0, y1]
  /// overlaps: all circles whose bounding box meets it, and some others. Same order as ForEachNear.
  template <class F>
  void ForEachInBox(double x0, double y0, double x1, double y1, F&& f) const;

  int Columns() const { return nx_; }
  int Rows() const { return ny_; }
  double CellSize() const { return cell_; }

  /// m: a side of about three foot-bot diameters. A scanner's disc (1.51 m) spans 7 × 7
  /// cells, the proximity ring's (0.19 m) one to four; smaller cells file each robot in
  /// more of them, larger ones let more far shapes through.
  static constexpr double kCellSize = 0.5;

 private:
  int Column(double x) const;
  int Row(double y) const;

  std::vector<GridCircle> circles_;
  std::vector<int> cell_start_;  // (cells + 1): circles of cell k are filed[cell_start_[k] .. cell_start_[k+1])
  std::vector<int> filed_;       // indices into circles_
  double x0_ = 0, y0_ = 0;       // m, lower-left corner of cell (0, 0)
  double cell_ = kCellSize, inv_cell_ = 1 / kCellSize;
  int nx_ = 0, ny_ = 0;
};

namespace grid_detail {
/// Cell coordinate `t` clamped to [0, n - 1] while still a double: far or NaN points convert safely.
inline int Clamp(double t, int n) {
  if (!(t >= 0)) return 0;
  if (t > n - 1) return n - 1;
  return static_cast<int>(t);
}
}  // namespace grid_detail

inline int ShapeGrid::Column(double x) const { return grid_detail::Clamp((x - x0_) * inv_cell_, nx_); }
inline int ShapeGrid::Row(double y) const { return grid_detail::Clamp((y - y0_) * inv_cell_, ny_); }

template <class F>
void ShapeGrid::ForEachInBox(double x0, double y0, double x1, double y1, F&& f) const {
  if (nx_ == 0) return;
  const int cx0 = Column(x0), cx1 = Column(x1);
  const int cy0 = Row(y0), cy1 = Row(y1);
  for (int row = cy0; row <= cy1; ++row) {
    for (int col = cx0; col <= cx1; ++col) {
      const int cell = row * nx_ + col;
      for (int k = cell_start_[cell], end = cell_start_[cell + 1]; k < end; ++k) {
        const GridCircle& c = circles_[filed_[k]];
        // A circle filed in several cells is reported from the first of them in the query.
        if (col != (c.x0 > cx0 ? c.x0 : cx0) || row != (c.y0 > cy0 ? c.y0 : cy0)) continue;
        f(c);
      }
    }
  }
}

}  // namespace essaim
