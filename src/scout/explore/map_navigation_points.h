#ifndef SCOUT_EXPLORE_MAP_NAVIGATION_POINTS_H_
#define SCOUT_EXPLORE_MAP_NAVIGATION_POINTS_H_

#include <Eigen/Core>
#include <vector>

#include "scout/explore/navigation_points.h"
#include "scout/explore/planning_map.h"
#include "scout/grid/occupancy_map.h"

namespace scout::explore {

// The navigation points of one map as it stands, without a robot driving to
// them: where an explorer would go next from 'robot' on a recorded run (the
// frontier-only mode users of the peers ask for). The same path costs and
// ranking as the exploration loop's first selection from that pose.
struct MapNavigationPoints {
  std::vector<NavigationPoint> points;  // best revenue first
  NavigationPointStats stats;
  // The robot stood where its disc does not fit (closer to a wall than the
  // inflation) and the paths start where it can leave (StartRegion).
  bool robot_escaped = false;
  // No traversable cell was found around the robot: every point is unreachable.
  bool robot_boxed_in = false;
  // Frontier points inside the boundary (all of them without one).
  int frontier_points_in_boundary = 0;
};

// 'frontier' are global frontier points in the map frame; 'driven' the robot's
// positions so far (cells along them stay passable, TraversabilityOptions::
// driven_width_m), empty for none. With a 'boundary' polygon (map frame, at
// least three vertices; empty: none), frontier points outside it are left
// out, as the goal manager leaves them out.
MapNavigationPoints NavigationPointsOnMap(const grid::OccupancyMap& map,
                                          const std::vector<Eigen::Vector2d>& frontier,
                                          const Eigen::Vector2d& robot,
                                          const std::vector<Eigen::Vector2d>& driven,
                                          const TraversabilityOptions& traversability,
                                          const NavigationPointOptions& options,
                                          const std::vector<Eigen::Vector2d>& boundary = {});

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_MAP_NAVIGATION_POINTS_H_
