// The one uniform grid: items (points, or boxes filed in every cell they cover) bucketed
// into square cells by the counting sort, rebuilt whole when they move, without
// allocating once warm. Cell coordinates are clamped, so items and queries outside the
// covered box land in the border cells: queries get slower there, never wrong.
// Plain indices and doubles: what an item is stays with the caller.
#pragma once
#include <vector>

#include "core/math.h"
#include "spatial/bucket_sort.h"

namespace essaim {

class UniformGrid {
 public:
  /// The items filed in a run of consecutive cells, ascending within each cell.
  struct Items {
    const int* first;
    const int* last;
    const int* begin() const { return first; }
    const int* end() const { return last; }
  };

  /// Cells of about `cell` m over the box [min, max], at most about `max_cells` of them
  /// (cells grow by half until they fit). For grids over the arena.
  void CoverBox(const Vec2& min, const Vec2& max, double cell, size_t max_cells);
  /// Cells of `cell` m from `min`, enough to reach `max`, doubled in size until there are
  /// at most `max_cells`. For grids over whatever the items span this time; a non-finite
  /// span gets one cell.
  void CoverSpan(const Vec2& min, const Vec2& max, double cell, double max_cells);
  /// Room for `entries` filed entries of up to `items` items, so that later filings within
  /// those bounds allocate nothing.
  void Reserve(size_t entries, size_t items);

  /// Files points 0..n-1 (pos(i)), one cell each.
  template <class PosFn>
  void FilePoints(int n, PosFn&& pos);
  /// Files boxes 0..n-1 ([lo(i), hi(i)]) in every cell they overlap. Only a grid of boxes
  /// answers ForEachOnceInBox.
  template <class LoFn, class HiFn>
  void FileBoxes(int n, LoFn&& lo, HiFn&& hi);

  /// Items of cells col0..col1 of `row` (consecutive in memory: one range).
  Items RowItems(int row, int col0, int col1) const {
    return {items_.data() + cell_start_[row * columns_ + col0], items_.data() + cell_start_[row * columns_ + col1 + 1]};
  }
  /// Calls f(item) for every entry of the cells the box [x0, x1] × [y0, y1] overlaps, cells
  /// row by row: every item whose filed box meets it, and some others; a box filed in
  /// several of those cells comes once per cell.
  template <class F>
  void ForEachInBox(double x0, double y0, double x1, double y1, F&& f) const;
  /// Whether pred(item) holds for some entry ForEachInBox would visit; stops at the first.
  template <class Pred>
  bool AnyInBox(double x0, double y0, double x1, double y1, Pred&& pred) const;
  /// Same as ForEachInBox, each item once: a box filed in several of the cells comes from the first of
  /// them (FileBoxes keeps each item's first cell). Same order otherwise.
  template <class F>
  void ForEachOnceInBox(double x0, double y0, double x1, double y1, F&& f) const;

  /// Cell column (row) of coordinate x (y), clamped to the grid: any double, NaN and ±inf
  /// included, lands in a valid cell.
  int Column(double x) const { return Clamp((x - origin_.x()) * inv_cell_, columns_); }
  int Row(double y) const { return Clamp((y - origin_.y()) * inv_cell_, rows_); }
  int Columns() const { return columns_; }
  int Rows() const { return rows_; }
  double CellSize() const { return cell_; }
  const Vec2& Origin() const { return origin_; }
  /// Upper bound of the cells a disc of `radius` overlaps.
  size_t DiscCells(double radius) const;

 private:
  /// floor(t) clamped to [0, n - 1] while still a double: far or NaN coordinates convert safely.
  static int Clamp(double t, int n) {
    if (!(t >= 0)) return 0;
    if (t > n - 1) return n - 1;
    return static_cast<int>(t);
  }
  void SetCells(const Vec2& origin, double cell, int columns, int rows);

  Vec2 origin_ = Vec2::Zero();  // m, lower-left corner of cell (0, 0)
  double cell_ = 1, inv_cell_ = 1;
  int columns_ = 1, rows_ = 1;
  /// (cells + 1): cell k's items are items_[cell_start_[k] .. cell_start_[k + 1]).
  std::vector<int> cell_start_ = {0, 0};
  std::vector<int> items_;                     // item numbers grouped by cell
  std::vector<int> first_column_, first_row_;  // per item: the first cell it is filed in
};

template <class PosFn>
void UniformGrid::FilePoints(int n, PosFn&& pos) {
  if (items_.size() < static_cast<size_t>(n)) items_.resize(n);
  auto cell_of = [&](int i, auto&& file) {
    const Vec2 p = pos(i);
    file(Row(p.y()) * columns_ + Column(p.x()));
  };
  BucketSort(n, &cell_start_, cell_of, [&](int slot, int i) { items_[slot] = i; });
}

template <class LoFn, class HiFn>
void UniformGrid::FileBoxes(int n, LoFn&& lo, HiFn&& hi) {
  first_column_.resize(n);
  first_row_.resize(n);
  for (int i = 0; i < n; ++i) {
    const Vec2 a = lo(i);
    first_column_[i] = Column(a.x());
    first_row_[i] = Row(a.y());
  }
  auto cells_of = [&](int i, auto&& file) {
    const Vec2 b = hi(i);
    for (int row = first_row_[i], y1 = Row(b.y()); row <= y1; ++row)
      for (int col = first_column_[i], x1 = Column(b.x()); col <= x1; ++col) file(row * columns_ + col);
  };
  size_t total = 0;
  for (int i = 0; i < n; ++i) cells_of(i, [&](int) { ++total; });
  if (items_.size() < total) items_.resize(total);
  BucketSort(n, &cell_start_, cells_of, [&](int slot, int i) { items_[slot] = i; });
}

template <class F>
void UniformGrid::ForEachInBox(double x0, double y0, double x1, double y1, F&& f) const {
  const int col0 = Column(x0), col1 = Column(x1);
  for (int row = Row(y0), row1 = Row(y1); row <= row1; ++row)
    for (int col = col0; col <= col1; ++col)
      for (int i : RowItems(row, col, col)) f(i);
}

template <class Pred>
bool UniformGrid::AnyInBox(double x0, double y0, double x1, double y1, Pred&& pred) const {
  const int col0 = Column(x0), col1 = Column(x1);
  for (int row = Row(y0), row1 = Row(y1); row <= row1; ++row)
    for (int col = col0; col <= col1; ++col)
      for (int i : RowItems(row, col, col))
        if (pred(i)) return true;
  return false;
}

template <class F>
void UniformGrid::ForEachOnceInBox(double x0, double y0, double x1, double y1, F&& f) const {
  const int col0 = Column(x0), col1 = Column(x1);
  const int row0 = Row(y0), row1 = Row(y1);
  for (int row = row0; row <= row1; ++row)
    for (int col = col0; col <= col1; ++col)
      for (int i : RowItems(row, col, col)) {
        // An item filed in several cells is reported from the first of them in the query.
        if (col != (first_column_[i] > col0 ? first_column_[i] : col0) ||
            row != (first_row_[i] > row0 ? first_row_[i] : row0))
          continue;
        f(i);
      }
}

}  // namespace essaim
