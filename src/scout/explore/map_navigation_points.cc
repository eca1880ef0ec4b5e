#include "scout/explore/map_navigation_points.h"

#include <optional>

#include "scout/explore/goal_manager.h"
#include "scout/explore/path_distance_field.h"
#include "scout/explore/start_region.h"

namespace scout::explore {

MapNavigationPoints NavigationPointsOnMap(const grid::OccupancyMap& map,
                                          const std::vector<Eigen::Vector2d>& frontier,
                                          const Eigen::Vector2d& robot,
                                          const std::vector<Eigen::Vector2d>& driven,
                                          const TraversabilityOptions& traversability,
                                          const NavigationPointOptions& options,
                                          const std::vector<Eigen::Vector2d>& boundary) {
  MapNavigationPoints result;
  std::vector<Eigen::Vector2d> inside;
  for (const Eigen::Vector2d& p : frontier) {
    if (boundary.empty() || InsidePolygon(boundary, p)) inside.push_back(p);
  }
  result.frontier_points_in_boundary = static_cast<int>(inside.size());
  PlanningMap planning(map, traversability);
  if (!driven.empty()) planning.AllowDriven(driven);
  const StartRegion start(planning, robot);
  result.robot_escaped = start.escaped();
  result.robot_boxed_in = start.empty();
  const PathDistanceField distances(planning, start);
  result.points = ComputeNavigationPoints(planning, distances, inside, robot,
                                          /*current_goal=*/std::nullopt, options, &result.stats);
  return result;
}

}  // namespace scout::explore
