#include "scout/sim/ray_caster.h"

#include <cmath>
#include <limits>

namespace scout::sim {

double CastRay(const grid::OccupancyMap& map, const Eigen::Vector2d& origin, double angle_rad,
               double max_range_m) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const double resolution_m = map.limits.resolution();
  // Work in cell units: cell (x, y) covers [x, x + 1) x [y, y + 1).
  const Eigen::Vector2d start = (origin - map.limits.origin()) / resolution_m;
  const Eigen::Vector2d direction(std::cos(angle_rad), std::sin(angle_rad));
  grid::CellIndex cell{static_cast<int>(std::floor(start.x())),
                       static_cast<int>(std::floor(start.y()))};
  const int step_x = direction.x() > 0.0 ? 1 : -1;
  const int step_y = direction.y() > 0.0 ? 1 : -1;
  // Ray parameter (distance in cells) at which the next x / y cell border is crossed.
  double next_x = kInfinity, next_y = kInfinity;
  double delta_x = kInfinity, delta_y = kInfinity;
  if (direction.x() != 0.0) {
    next_x = ((cell.x + (step_x > 0 ? 1 : 0)) - start.x()) / direction.x();
    delta_x = 1.0 / std::abs(direction.x());
  }
  if (direction.y() != 0.0) {
    next_y = ((cell.y + (step_y > 0 ? 1 : 0)) - start.y()) / direction.y();
    delta_y = 1.0 / std::abs(direction.y());
  }
  const double limit = max_range_m / resolution_m;
  double t = 0.0;
  while (t <= limit) {
    if (map.at(cell) != grid::CellState::kFree) return t * resolution_m;
    if (next_x < next_y) {
      t = next_x;
      next_x += delta_x;
      cell.x += step_x;
    } else {
      t = next_y;
      next_y += delta_y;
      cell.y += step_y;
    }
  }
  return kInfinity;
}

}  // namespace scout::sim
