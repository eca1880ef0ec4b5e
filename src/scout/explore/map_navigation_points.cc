#include "scout/explore/map_navigation_points.h"

#include <optional>

#include "scout/explore/path_distance_field.h"
#include "scout/explore/start_region.h"

namespace scout::explore {

MapNavigationPoints NavigationPointsOnMap(const grid::OccupancyMap& map,
                                          const std::vector<Eigen::Vector2d>& frontier,
                                          const Eigen::Vector2d& robot,
                                          const std::vector<Eigen::Vector2d>& driven,
                                          const TraversabilityOptions& traversability,
                                          const NavigationPointOptions& options) {
  MapNavigationPoints result;
  PlanningMap planning(map, traversability);
  if (!driven.empty()) planning.AllowDriven(driven);
  const StartRegion start(planning, robot);
  result.robot_escaped = start.escaped();
  result.robot_boxed_in = start.empty();
  const PathDistanceField distances(planning, start);
  result.points = ComputeNavigationPoints(planning, distances, frontier, robot,
                                          /*current_goal=*/std::nullopt, options, &result.stats);
  return result;
}

}  // namespace scout::explore
