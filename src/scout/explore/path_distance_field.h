#ifndef SCOUT_EXPLORE_PATH_DISTANCE_FIELD_H_
#define SCOUT_EXPLORE_PATH_DISTANCE_FIELD_H_

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "scout/explore/planning_map.h"
#include "scout/explore/start_region.h"

namespace scout::explore {

// Path distance from the robot to every cell over a PlanningMap: one Dijkstra
// (8-connected, steps of 1 and sqrt 2 cells, same step rule as the A* planner)
// gives the cost of every navigation point at once.
class PathDistanceField {
 public:
  static constexpr float kUnreachable = std::numeric_limits<float>::infinity();

  // Starts where the robot enters the traversable cells (StartRegion: its
  // own cell, or the cells its bare disc reaches when it stands in the
  // inflated band). With no such cell every distance is kUnreachable.
  PathDistanceField(const PlanningMap& map, const Eigen::Vector2d& robot);
  // Starts at the seeds of 'start', which must come from 'map'.
  PathDistanceField(const PlanningMap& map, const StartRegion& start);

  // Returns the path distance in metres to the cell (kUnreachable if none).
  float at(int64_t flat) const {
    return distance_cells_[flat + 2 * (flat / limits_.width()) + padded_width() + 1] * res_;
  }
  // As above; kUnreachable outside the map.
  float at(const grid::CellIndex& cell) const {
    return limits_.Contains(cell) ? distance_cells_[Padded(cell)] * res_ : kUnreachable;
  }
  // The seed cell nearest the robot by path, if any.
  const std::optional<grid::CellIndex>& start() const { return start_; }

  // Returns the least distance over the cells within 'radius_m' of 'p' (the cell
  // containing 'p' always counts), and that cell; nothing when none is reached.
  // The radius absorbs the rounding between a submap's lattice and the map's.
  struct Reached {
    float distance_m;
    grid::CellIndex cell;
  };
  std::optional<Reached> NearestReached(const Eigen::Vector2d& p, double radius_m) const;

 private:
  int64_t padded_width() const { return limits_.width() + 2; }
  int64_t Padded(const grid::CellIndex& c) const {
    return (int64_t{c.y} + 1) * padded_width() + c.x + 1;
  }

  grid::MapLimits limits_;
  float res_;  // metres per cell
  std::optional<grid::CellIndex> start_;
  // Path distances in cells (metres: times res_). The grid is padded by one
  // unreachable cell on every side, so the search's inner loop needs no
  // bounds checks (index with Padded).
  std::vector<float> distance_cells_;
};

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_PATH_DISTANCE_FIELD_H_
