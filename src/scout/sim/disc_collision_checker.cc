#include "scout/sim/disc_collision_checker.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "scout/common/format.h"
#include "scout/geometry/box.h"
#include "scout/sim/clearance.h"

namespace scout::sim {
namespace {

// Returns the distance from 'p' to the closed square of 'cell'.
double DistanceToCell(const grid::MapLimits& limits, const grid::CellIndex& cell,
                      const Eigen::Vector2d& p) {
  const double res = limits.resolution();
  const Eigen::Vector2d min_corner = limits.origin() + res * Eigen::Vector2d(cell.x, cell.y);
  return geometry::Box2d(min_corner, min_corner + Eigen::Vector2d(res, res)).DistanceTo(p);
}

}  // namespace

DiscCollisionChecker::DiscCollisionChecker(const grid::OccupancyMap& map, double radius_m)
    : limits_(map.limits), radius_m_(radius_m), clearance_m_(ComputeClearance(map)) {
  if (!(radius_m > 0.0)) {
    throw std::invalid_argument("DiscCollisionChecker: radius_m = " + FormatNumber(radius_m) +
                                ", expected > 0");
  }
  half_diagonal_m_ = limits_.resolution() * std::sqrt(0.5);
}

bool DiscCollisionChecker::IsObstacle(const grid::CellIndex& cell) const {
  return !limits_.Contains(cell) || clearance_m_[limits_.FlatIndex(cell)] == 0.f;
}

bool DiscCollisionChecker::Collides(const Eigen::Vector2d& center, double radius_m) const {
  const grid::CellIndex cell = limits_.CellContaining(center);
  if (IsObstacle(cell)) return true;
  // The clearance is a rounded float: a margin far below anything the robot
  // could notice keeps both shortcuts conservative.
  constexpr double kRoundingMarginM = 1e-6;
  const double clearance_m = clearance_m_[limits_.FlatIndex(cell)];
  if (clearance_m >= radius_m + 2.0 * half_diagonal_m_ + kRoundingMarginM) return false;
  if (clearance_m < radius_m - half_diagonal_m_ - kRoundingMarginM) return true;
  return ExactDistanceToObstacle(center, radius_m) < radius_m;
}

double DiscCollisionChecker::ExactDistanceToObstacle(const Eigen::Vector2d& p,
                                                     double search_radius_m) const {
  const Eigen::Vector2d reach(search_radius_m, search_radius_m);
  const grid::CellIndex lo = limits_.CellContaining(p - reach);
  const grid::CellIndex hi = limits_.CellContaining(p + reach);
  double nearest_m = search_radius_m;
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      if (IsObstacle({x, y})) nearest_m = std::min(nearest_m, DistanceToCell(limits_, {x, y}, p));
    }
  }
  return nearest_m;
}

}  // namespace scout::sim
