#ifndef SCOUT_EXPLORE_START_REGION_H_
#define SCOUT_EXPLORE_START_REGION_H_

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "scout/explore/planning_map.h"

namespace scout::explore {

// A traversable cell where a search from the robot begins, and the cost of
// the robot's way to its centre (its length; escape steps weighted like
// narrow passages).
struct StartSeed {
  grid::CellIndex cell;
  float distance_m = 0.0f;
};

// Where the robot enters the traversable cells of a PlanningMap. The path
// distance field and the planner both start from it, so every navigation
// point with a cost has a plan.
//
// A robot whose (estimated) cell is traversable starts there. A robot closer
// to a wall than that (estimate error, a wall seen late), or boxed in a pocket
// of traversable cells, must still be able to leave: the escape search walks
// from the robot's cell, within escape_radius_m, over free cells (or the
// robot's own footprint) where the disc keeps robot_radius_m +
// narrow_margin_m from occupied cells, or at least the clearance it has where
// it stands; every traversable cell it reaches becomes a seed. Seeding only
// the nearest traversable cell would strand the robot when that cell is an
// isolated pocket (the search then reaches no frontier and exploration
// "completes" early).
class StartRegion {
 public:
  // With 'escape', escapes even from a traversable cell (the caller found the
  // robot boxed in); otherwise only from a cell that is not traversable.
  StartRegion(const PlanningMap& map, const Eigen::Vector2d& robot, bool escape = false);

  // The seeds, in row-major order of their cells; empty when the robot can
  // reach no traversable cell.
  const std::vector<StartSeed>& seeds() const { return seeds_; }
  bool empty() const { return seeds_.empty(); }
  // True when the seeds come from the escape search.
  bool escaped() const { return escaped_; }
  const Eigen::Vector2d& robot() const { return robot_; }

  // Returns the robot's way to the seed cell 'cell' as world points: the
  // robot's position, then the centres of the cells passed, ending at the
  // seed's centre (just the robot and the centre without escape). Requires
  // 'cell' to be a seed.
  std::vector<Eigen::Vector2d> PathTo(const grid::CellIndex& cell) const;

 private:
  void Escape(const PlanningMap& map);
  int64_t WindowIndex(const grid::CellIndex& c) const {
    return int64_t{c.y - window_min_.y} * window_width_ + (c.x - window_min_.x);
  }

  Eigen::Vector2d robot_;
  grid::MapLimits limits_;
  bool escaped_ = false;
  std::vector<StartSeed> seeds_;
  // Escape search tree over the window around the robot: parent offset index
  // (kNeighbourOffsets) per cell, 255 for the root or unreached cells.
  grid::CellIndex window_min_{0, 0};
  int window_width_ = 0;
  int window_height_ = 0;
  grid::CellIndex root_{0, 0};
  std::vector<uint8_t> parent_;
};

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_START_REGION_H_
