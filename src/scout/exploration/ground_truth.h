#ifndef SCOUT_EXPLORATION_GROUND_TRUTH_H_
#define SCOUT_EXPLORATION_GROUND_TRUTH_H_

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "scout/explore/planning_map.h"
#include "scout/geometry/rigid_transform.h"
#include "scout/grid/occupancy_map.h"

namespace scout::exploration {

// Evaluation against the TRUE world (the simulator's map), which the robot
// never sees: how much of what it could explore is mapped, and whether a goal
// could be reached at all.
//
// Reachable free area: the robot's centre may go wherever the explorer's own
// traversability allows (robot radius + safety margin from walls, unknown
// space excluded) starting from the start; every free cell its disc covers
// from there counts. Space behind gaps narrower than the inflated robot is
// excluded on purpose: Scout does not drive through them (ALGORITHMS §2), so
// counting it would only measure the world, not the exploration.
// Beyond the world's map is an obstacle, as in the simulator.
class GroundTruth {
 public:
  // 'traversability' is the explorer's; 'robot_radius_m' the bare disc.
  // With a 'boundary' polygon (world frame; empty: none), it counts as a
  // wall: only free cells the disc reaches and covers without its centre
  // leaving the polygon count.
  // Throws InputError naming the world when the start is not a free position
  // for the disc (suggesting --start X,Y), nothing is reachable from it, or
  // the start or everything reachable lies outside the boundary.
  GroundTruth(const grid::OccupancyMap& world, const std::string& world_name,
              const Eigen::Vector2d& start, const explore::TraversabilityOptions& traversability,
              double robot_radius_m, const std::vector<Eigen::Vector2d>& boundary = {});

  // Returns the reachable free area in m².
  double reachable_free_m2() const { return reachable_cells_ * cell_area_m2_; }
  // Returns the reachable free area (m²) that 'map' shows as free, where
  // 'world_from_map' places the map in the world frame.
  double MappedFreeM2(const grid::OccupancyMap& map, const geometry::Rigid2d& world_from_map) const;
  // What MappedFreeM2 counts, cell by cell on limits() (row-major):
  // kNotReachable, kUnmapped (reachable, not free in 'map') or kMapped.
  enum CoverageCell : uint8_t { kNotReachable = 0, kUnmapped = 1, kMapped = 2 };
  std::vector<uint8_t> CoverageMask(const grid::OccupancyMap& map,
                                    const geometry::Rigid2d& world_from_map) const;

  // True when the bare disc can drive from 'from' to within 'tolerance_m' of
  // 'goal' in the true world (world frame). Unknown space is not traversable.
  bool DiscCanReach(const Eigen::Vector2d& from, const Eigen::Vector2d& goal,
                    double tolerance_m) const;

  const grid::MapLimits& limits() const { return limits_; }
  // Row-major mask of the reachable free cells, on limits().
  std::vector<uint8_t> ReachableMask() const;

 private:
  // Labels of the 4-connected components of cells the bare disc's centre may
  // occupy (0: none). 4-connectivity equals the planner's 8-connected step
  // rule, which forbids cutting blocked corners.
  void LabelDiscComponents(const explore::PlanningMap& bare);
  // Calls f(cell, mapped) for every reachable cell, in row-major order.
  template <typename F>
  void ForEachReachable(const grid::OccupancyMap& map, const geometry::Rigid2d& world_from_map,
                        F&& f) const;
  // The constructor's work, on the world already walled in.
  GroundTruth(const grid::OccupancyMap& world, const std::string& world_name,
              const Eigen::Vector2d& start, const explore::TraversabilityOptions& traversability,
              double robot_radius_m, const std::vector<Eigen::Vector2d>& boundary, bool walled);

  grid::MapLimits limits_;
  double cell_area_m2_ = 0.0;
  // The reachable free cells, row-major, while the constructors find them;
  // then kept as runs of adjacent cells of a row (a fifth of the memory that
  // ForEachReachable streams through at every map update).
  std::vector<grid::CellIndex> reachable_;
  struct Run {
    int y = 0;
    int x = 0;  // the first cell
    int length = 0;
  };
  std::vector<Run> runs_;
  int64_t reachable_cells_ = 0;
  std::vector<int32_t> disc_component_;
};

}  // namespace scout::exploration

#endif  // SCOUT_EXPLORATION_GROUND_TRUTH_H_
