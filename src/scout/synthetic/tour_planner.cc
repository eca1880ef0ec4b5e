#include "scout/synthetic/tour_planner.h"

#include <deque>
#include <limits>
#include <string>

#include "scout/common/error.h"
#include "scout/common/format.h"
#include "scout/sim/clearance.h"
#include "scout/synthetic/grid_search.h"
#include "scout/synthetic/path_smoothing.h"
#include "scout/synthetic/waypoint_cover.h"

namespace scout::synthetic {
namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

void RequireTourOption(bool ok, const std::string& key, double value, const std::string& expected) {
  if (!ok) {
    throw InputError("tour." + key + " = " + FormatNumber(value) + ": expected " + expected);
  }
}

// Returns the traversable cell nearest to 'source' (breadth-first over free
// cells, 8-connected), or -1.
int64_t NearestTraversable(const grid::OccupancyMap& map, const GridSearch& search,
                           int64_t source) {
  const grid::MapLimits& limits = map.limits;
  std::vector<uint8_t> visited(map.cells.size(), 0);
  std::deque<int64_t> queue = {source};
  visited[source] = 1;
  while (!queue.empty()) {
    const int64_t flat = queue.front();
    queue.pop_front();
    if (search.traversable(flat)) return flat;
    const grid::CellIndex cell = limits.CellOfFlatIndex(flat);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const grid::CellIndex next{cell.x + dx, cell.y + dy};
        if (!limits.Contains(next)) continue;
        const int64_t next_flat = limits.FlatIndex(next);
        if (visited[next_flat] || map.cells[next_flat] != grid::CellState::kFree) continue;
        visited[next_flat] = 1;
        queue.push_back(next_flat);
      }
    }
  }
  return -1;
}

// Turns a grid path into a short, rounded polyline that keeps the clearance.
std::vector<Eigen::Vector2d> SmoothLeg(const std::vector<int64_t>& cells, const GridSearch& search,
                                       const std::vector<float>& clearance, const TourOptions& o) {
  const grid::MapLimits& limits = search.limits();
  std::vector<Eigen::Vector2d> points;
  for (int64_t cell : cells) points.push_back(limits.CellCenter(limits.CellOfFlatIndex(cell)));
  const auto clearance_at = [&](const Eigen::Vector2d& p) -> float {
    const grid::CellIndex cell = limits.CellContaining(p);
    return limits.Contains(cell) ? clearance[limits.FlatIndex(cell)] : 0.f;
  };
  const auto traversable = [&](const Eigen::Vector2d& p) {
    return clearance_at(p) >= o.path_clearance_m;
  };
  const std::vector<Eigen::Vector2d> shortcut =
      ShortcutPath(points, traversable, o.max_shortcut_m, 0.5 * limits.resolution());
  const std::vector<Eigen::Vector2d> rounded =
      RoundCorners(shortcut, o.smoothing_spacing_m, o.smoothing_iterations);
  for (const Eigen::Vector2d& p : rounded) {
    if (clearance_at(p) < o.min_pose_clearance_m) return shortcut;
  }
  return rounded;
}

}  // namespace

void Validate(const TourOptions& o) {
  RequireTourOption(o.path_clearance_m >= 0.0, "path_clearance_m", o.path_clearance_m, ">= 0");
  RequireTourOption(o.waypoint_clearance_m >= o.path_clearance_m, "waypoint_clearance_m",
                    o.waypoint_clearance_m, ">= path_clearance_m");
  RequireTourOption(o.waypoint_spacing_m > 0.0, "waypoint_spacing_m", o.waypoint_spacing_m, "> 0");
  RequireTourOption(o.max_shortcut_m > 0.0, "max_shortcut_m", o.max_shortcut_m, "> 0");
  RequireTourOption(o.smoothing_spacing_m > 0.0, "smoothing_spacing_m", o.smoothing_spacing_m,
                    "> 0");
  RequireTourOption(o.smoothing_iterations >= 0, "smoothing_iterations", o.smoothing_iterations,
                    ">= 0");
  RequireTourOption(o.min_pose_clearance_m >= 0.0 && o.min_pose_clearance_m <= o.path_clearance_m,
                    "min_pose_clearance_m", o.min_pose_clearance_m, "in [0, path_clearance_m]");
}

std::vector<Eigen::Vector2d> PlanTour(const sim::World& world, const TourOptions& o) {
  Validate(o);
  const grid::OccupancyMap& map = world.map;
  const grid::MapLimits& limits = map.limits;
  const std::vector<float> clearance = sim::ComputeClearance(map);
  std::vector<uint8_t> traversable(clearance.size());
  for (size_t i = 0; i < clearance.size(); ++i) {
    traversable[i] = clearance[i] >= o.path_clearance_m ? 1 : 0;
  }
  GridSearch search(limits, std::move(traversable));

  const std::string where = "world '" + world.name + "'";
  const grid::CellIndex start_cell = limits.CellContaining(world.start);
  if (!limits.Contains(start_cell) || map.at(start_cell) != grid::CellState::kFree) {
    throw InputError(where + ": the start is not in free space");
  }
  std::vector<Eigen::Vector2d> tour = {world.start};
  const int64_t source = NearestTraversable(map, search, limits.FlatIndex(start_cell));
  if (source < 0) {
    throw InputError(where + ": no free space with clearance " + FormatNumber(o.path_clearance_m) +
                     " m is reachable from the start");
  }
  if (source != limits.FlatIndex(start_cell)) {
    tour.push_back(limits.CellCenter(limits.CellOfFlatIndex(source)));
  }

  std::vector<uint8_t> reachable(clearance.size(), 0);
  search.Run(source, kUnbounded, [&](int64_t cell, double) {
    reachable[cell] = 1;
    return false;
  });
  const std::vector<int64_t> waypoints =
      SelectWaypoints(search, reachable, clearance, o.waypoint_clearance_m, o.waypoint_spacing_m);
  std::vector<std::vector<int64_t>> legs = OrderByNearestNeighbour(search, source, waypoints);
  const int64_t last = legs.empty() ? source : legs.back().back();
  if (o.return_to_start && last != source) {
    search.Run(last, kUnbounded, [&](int64_t cell, double) { return cell == source; });
    legs.push_back(search.PathTo(source));
  }
  for (const std::vector<int64_t>& leg : legs) {
    const std::vector<Eigen::Vector2d> points = SmoothLeg(leg, search, clearance, o);
    // The first point repeats the end of the previous leg.
    tour.insert(tour.end(), points.begin() + 1, points.end());
  }
  return tour;
}

}  // namespace scout::synthetic
