#ifndef SCOUT_SIM_DISC_COLLISION_CHECKER_H_
#define SCOUT_SIM_DISC_COLLISION_CHECKER_H_

#include <Eigen/Core>
#include <vector>

#include "scout/grid/map_limits.h"
#include "scout/grid/occupancy_map.h"

namespace scout::sim {

// Answers "does a disc of radius R centred at p overlap an obstacle cell?" for
// a fixed map, where obstacles are occupied and unknown cells and everything
// beyond the map (cells are squares; touching a cell's border is not an
// overlap).
//
// Built once from the map's clearance (an exact Euclidean distance transform
// between cell centres, see clearance.h). The clearance D of the cell holding p
// bounds the distance from p to every obstacle square within
// [D - sqrt(2) res, D + res / sqrt(2)], so outside a band of about 2 cells
// around radius R one table lookup decides (O(1)); inside the band the cells
// under the disc are tested exactly, O((R / res)^2).
class DiscCollisionChecker {
 public:
  // Throws std::invalid_argument unless radius_m > 0.
  DiscCollisionChecker(const grid::OccupancyMap& map, double radius_m);

  // Returns true if the disc centred at 'center' overlaps an obstacle cell.
  bool Collides(const Eigen::Vector2d& center) const { return Collides(center, radius_m_); }
  // The same for a disc of another radius (e.g. with a safety margin added).
  bool Collides(const Eigen::Vector2d& center, double radius_m) const;

  // Returns the exact distance from 'p' to the nearest obstacle cell (0 inside
  // one), by brute force over the cells within 'search_radius_m'; returns
  // search_radius_m if none is closer. For tests and diagnostics.
  double ExactDistanceToObstacle(const Eigen::Vector2d& p, double search_radius_m) const;

  double radius_m() const { return radius_m_; }
  const grid::MapLimits& limits() const { return limits_; }

 private:
  bool IsObstacle(const grid::CellIndex& cell) const;

  grid::MapLimits limits_;
  double radius_m_;
  // Clearance per cell in metres (0 exactly for obstacle cells).
  std::vector<float> clearance_m_;
  // Bounds on how far p may be from its cell's centre and an obstacle square
  // from its own centre: clearance D decides "free" when D >= R + 2 of them,
  // "collides" when D < R - 1 of them.
  double half_diagonal_m_;
};

}  // namespace scout::sim

#endif  // SCOUT_SIM_DISC_COLLISION_CHECKER_H_
