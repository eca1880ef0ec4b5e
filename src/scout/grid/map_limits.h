#ifndef SCOUT_GRID_MAP_LIMITS_H_
#define SCOUT_GRID_MAP_LIMITS_H_

#include <Eigen/Core>
#include <cmath>
#include <cstdint>

#include "scout/geometry/box.h"

namespace scout::grid {

// A cell of a grid: column x, row y, counted from the min corner (the cell
// whose lower-left corner is the grid origin is (0, 0)). Everywhere in Scout.
struct CellIndex {
  int x = 0;
  int y = 0;
  friend bool operator==(const CellIndex&, const CellIndex&) = default;
};

// The geometry of a grid: resolution, the metric position of its min corner,
// and its size in cells. Cell (x, y) covers
// [origin.x + x * res, origin.x + (x + 1) * res) x [origin.y + y * res, ...).
class MapLimits {
 public:
  MapLimits() = default;
  // Throws std::invalid_argument unless resolution_m > 0 and sizes are >= 0.
  MapLimits(double resolution_m, const Eigen::Vector2d& origin, int width, int height);

  double resolution() const { return resolution_; }
  // Metric position of the min corner of cell (0, 0).
  const Eigen::Vector2d& origin() const { return origin_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int64_t num_cells() const { return static_cast<int64_t>(width_) * height_; }

  // Returns the cell containing 'p' (it may lie outside the grid).
  CellIndex CellContaining(const Eigen::Vector2d& p) const {
    return {static_cast<int>(std::floor((p.x() - origin_.x()) / resolution_)),
            static_cast<int>(std::floor((p.y() - origin_.y()) / resolution_))};
  }
  // Returns the metric centre of 'cell'.
  Eigen::Vector2d CellCenter(const CellIndex& cell) const {
    return {origin_.x() + (cell.x + 0.5) * resolution_, origin_.y() + (cell.y + 0.5) * resolution_};
  }
  bool Contains(const CellIndex& cell) const {
    return cell.x >= 0 && cell.y >= 0 && cell.x < width_ && cell.y < height_;
  }
  // Returns the row-major index y * width + x of a cell inside the grid.
  int64_t FlatIndex(const CellIndex& cell) const {
    return static_cast<int64_t>(cell.y) * width_ + cell.x;
  }
  CellIndex CellOfFlatIndex(int64_t flat) const {
    return {static_cast<int>(flat % width_), static_cast<int>(flat / width_)};
  }
  // Returns the metric box covered by all cells.
  geometry::Box2d Bounds() const {
    return {origin_, origin_ + Eigen::Vector2d(width_ * resolution_, height_ * resolution_)};
  }

 private:
  double resolution_ = 0.05;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  int width_ = 0;
  int height_ = 0;
};

}  // namespace scout::grid

#endif  // SCOUT_GRID_MAP_LIMITS_H_
