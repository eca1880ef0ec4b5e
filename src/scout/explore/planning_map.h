#ifndef SCOUT_EXPLORE_PLANNING_MAP_H_
#define SCOUT_EXPLORE_PLANNING_MAP_H_

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "scout/grid/map_limits.h"
#include "scout/grid/occupancy_map.h"

namespace scout::explore {

// Where the robot may be: one shared definition for navigation-point costs,
// the A* planner and the baselines, so a goal that has a cost also has a plan.
struct TraversabilityOptions {
  // The robot is a disc of this radius (ALGORITHMS §8).
  double robot_radius_m = 0.20;
  // Extra clearance kept from occupied cells; inflation = robot + margin, the
  // same 0.40 m the frontier detector inflates by (ALGORITHMS §2).
  double safety_margin_m = 0.20;
  // Unknown cells are not traversable by default: frontier points lie on the
  // known-free side (WFD only walks free cells), so every frontier is reachable
  // through known free space, and unseen space may hide obstacles.
  bool unknown_traversable = false;
  // A goal whose own cell is not traversable is approached at the nearest
  // reachable cell within this radius (metres). It absorbs the rounding
  // between a submap's lattice and the fused map's; 0 demands the goal's cell.
  double goal_snap_radius_m = 0.10;

  double inflation_radius_m() const { return robot_radius_m + safety_margin_m; }
};

// Throws std::invalid_argument naming the key of a bad value.
void Validate(const TraversabilityOptions& options);

// Returns the cells inside 'limits' whose centres lie within 'radius_m' of 'p'
// (the cell containing 'p' always included when inside), in row-major order.
std::vector<grid::CellIndex> CellsWithin(const grid::MapLimits& limits, const Eigen::Vector2d& p,
                                         double radius_m);

// 8-neighbour offsets; the first four are the orthogonal ones.
inline constexpr std::array<std::array<int, 2>, 8> kNeighbourOffsets = {
    {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}}};

// An occupancy map with the robot's footprint applied: every cell within the
// inflation radius of an occupied cell is blocked (exact EDT). Owns a copy of
// the states so it stays valid when the caller's map changes.
class PlanningMap {
 public:
  // With 'with_clearance', also keeps each cell's distance to the nearest
  // occupied cell (one more EDT) for planners that penalise closeness.
  PlanningMap(const grid::OccupancyMap& map, const TraversabilityOptions& options,
              bool with_clearance = false);

  const grid::MapLimits& limits() const { return limits_; }
  const TraversabilityOptions& options() const { return options_; }
  grid::CellState state(int64_t flat) const { return states_[flat]; }
  const std::vector<grid::CellState>& states() const { return states_; }
  // True when the cell lies within the inflation radius of an occupied cell.
  bool blocked(int64_t flat) const { return blocked_[flat] != 0; }
  // True when the robot's centre may be in this cell.
  bool traversable(int64_t flat) const { return traversable_[flat] != 0; }
  // As above; false for cells outside the map.
  bool Traversable(const grid::CellIndex& cell) const {
    return limits_.Contains(cell) && traversable(limits_.FlatIndex(cell));
  }
  // True when a step from 'from' by neighbour offset 'k' stays on traversable
  // cells; diagonal steps also need both orthogonal cells, so a path never
  // squeezes between two blocked corners.
  bool StepAllowed(const grid::CellIndex& from, int k) const;

  bool has_clearance() const { return !clearance_m_.empty(); }
  // Distance in metres from the cell's centre to the nearest occupied cell's
  // centre (+infinity without occupied cells). Requires has_clearance().
  float clearance_m(int64_t flat) const { return clearance_m_[flat]; }

  // Returns the traversable cell whose centre is nearest to 'p' within
  // 'radius_m' (ties: lowest flat index), or nothing.
  std::optional<grid::CellIndex> NearestTraversable(const Eigen::Vector2d& p,
                                                    double radius_m) const;
  // True when every cell the segment a-b passes through is traversable (exact
  // grid traversal; through a cell corner both side cells count).
  bool SegmentTraversable(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
  // Smallest clearance over the cells the segment a-b passes through.
  float SegmentClearance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;

 private:
  template <typename Visit>
  void ForEachCellOnSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                            Visit&& visit) const;

  grid::MapLimits limits_;
  TraversabilityOptions options_;
  std::vector<grid::CellState> states_;
  std::vector<uint8_t> blocked_;
  std::vector<uint8_t> traversable_;
  std::vector<float> clearance_m_;
};

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_PLANNING_MAP_H_
