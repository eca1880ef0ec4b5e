#include "scout/explore/navigation_points.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "scout/explore/option_check.h"
#include "scout/explore/tour.h"

namespace scout::explore {

void Validate(const NavigationPointOptions& o) {
  Validate(o.mean_shift);
  CheckAtLeast("navigation_points", "connectivity_margin_m", o.connectivity_margin_m, 0.0);
  CheckAtLeast("navigation_points", "info_radius_m", o.info_radius_m, 0.0);
  CheckAtLeast("navigation_points", "info_multiplier", o.info_multiplier, 0.0);
  CheckAtLeast("navigation_points", "info_visible_range_m", o.info_visible_range_m, 0.0);
  if (o.info_visible_range_m > kMaxInfoVisibleRange_m) {
    RejectOption("navigation_points", "info_visible_range_m",
                 "at most " + std::to_string(kMaxInfoVisibleRange_m) + " m",
                 o.info_visible_range_m);
  }
  CheckAtLeast("navigation_points", "hysteresis_radius_m", o.hysteresis_radius_m, 0.0);
  CheckAtLeast("navigation_points", "hysteresis_gain", o.hysteresis_gain, 0.0);
  if (o.tour_points != 0 && (o.tour_points < 2 || o.tour_points > kMaxTourPoints)) {
    RejectOption("navigation_points", "tour_points",
                 "0 (off) or 2 to " + std::to_string(kMaxTourPoints), o.tour_points);
  }
}

double UnknownAreaWithin(const PlanningMap& map, const Eigen::Vector2d& p, double radius_m,
                         bool outside_map_is_unknown) {
  const grid::MapLimits& limits = map.limits();
  const grid::CellIndex centre = limits.CellContaining(p);
  const int r = static_cast<int>(std::ceil(radius_m / limits.resolution())) + 1;
  const double r2 = radius_m * radius_m;
  int64_t unknown = 0;
  for (int y = centre.y - r; y <= centre.y + r; ++y) {
    for (int x = centre.x - r; x <= centre.x + r; ++x) {
      const grid::CellIndex c{x, y};
      if ((limits.CellCenter(c) - p).squaredNorm() > r2) continue;
      if (!limits.Contains(c)) {
        unknown += outside_map_is_unknown;
      } else {
        unknown += map.state(limits.FlatIndex(c)) == grid::CellState::kUnknown;
      }
    }
  }
  return static_cast<double>(unknown) * limits.resolution() * limits.resolution();
}

double UnknownAreaVisible(const PlanningMap& map, const Eigen::Vector2d& p, double range_m,
                          bool outside_map_is_unknown) {
  const grid::MapLimits& limits = map.limits();
  const double res = limits.resolution();
  const grid::CellIndex centre = limits.CellContaining(p);
  const int r = static_cast<int>(std::ceil(range_m / res)) + 1;
  const int side = 2 * r + 1;
  std::vector<uint8_t> seen(static_cast<size_t>(side) * side, 0);
  int64_t unknown = 0;
  constexpr int num_rays = 360;
  const double step = 0.5 * res;
  const int num_steps = static_cast<int>(range_m / step);
  for (int k = 0; k < num_rays; ++k) {
    const double a = 2.0 * std::numbers::pi * k / num_rays;
    const Eigen::Vector2d d(std::cos(a), std::sin(a));
    for (int i = 1; i <= num_steps; ++i) {
      const grid::CellIndex c = limits.CellContaining(p + d * (step * i));
      const int wx = c.x - centre.x + r, wy = c.y - centre.y + r;
      if (wx < 0 || wy < 0 || wx >= side || wy >= side) break;
      uint8_t& mark = seen[static_cast<size_t>(wy) * side + wx];
      if (!limits.Contains(c)) {
        if (!mark) unknown += outside_map_is_unknown;
        mark = 1;
        continue;
      }
      const grid::CellState state = map.state(limits.FlatIndex(c));
      if (state == grid::CellState::kOccupied) break;
      if (!mark && state == grid::CellState::kUnknown) ++unknown;
      mark = 1;
    }
  }
  return static_cast<double>(unknown) * res * res;
}

double MaxInfoGainM2(double resolution_m, const NavigationPointOptions& options) {
  // Both UnknownAreaWithin and UnknownAreaVisible count cells of the square
  // of 2 r + 1 cells around the point's cell, r = ceil(radius / res) + 1.
  const bool visible = options.info_visible_range_m > 0.0;
  const double radius_m = visible ? options.info_visible_range_m : options.info_radius_m;
  const double side = 2.0 * (std::ceil(radius_m / resolution_m) + 1.0) + 1.0;
  const double square_m2 = side * side * resolution_m * resolution_m;
  // And the cells counted, disjoint squares, lie inside a disc: those whose
  // centres lie within the radius inside the radius plus half a cell
  // diagonal; those holding a ray's point within range inside the range
  // plus a diagonal. The tighter the bound, the less of the path distance
  // field the goal manager settles (ScoreAbovePathCost).
  const double reach_m = radius_m + (visible ? std::sqrt(2.0) : std::sqrt(0.5)) * resolution_m;
  return std::min(square_m2, std::numbers::pi * reach_m * reach_m);
}

double InfoGain(const PlanningMap& map, const Eigen::Vector2d& p,
                const NavigationPointOptions& options) {
  return options.info_visible_range_m > 0.0
             ? UnknownAreaVisible(map, p, options.info_visible_range_m,
                                  options.outside_map_is_unknown)
             : UnknownAreaWithin(map, p, options.info_radius_m, options.outside_map_is_unknown);
}

std::vector<int> SplitByConnectivity(const PlanningMap& map,
                                     const std::vector<Eigen::Vector2d>& points, double margin_m) {
  std::vector<int> label(points.size(), -1);
  if (points.empty()) return label;
  const grid::MapLimits& limits = map.limits();
  // Window: the points' bounding box plus the margin, clipped to the map.
  Eigen::Vector2d lo = points[0], hi = points[0];
  for (const Eigen::Vector2d& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Eigen::Vector2d m(margin_m, margin_m);
  grid::CellIndex a = limits.CellContaining(lo - m), b = limits.CellContaining(hi + m);
  a = {std::max(a.x, 0), std::max(a.y, 0)};
  b = {std::min(b.x, limits.width() - 1), std::min(b.y, limits.height() - 1)};
  const int w = b.x - a.x + 1, h = b.y - a.y + 1;
  // The window's cells padded by one blocked cell on every side: kOpen until
  // a flood labels them, kBlocked where occupied (so the flood needs no bounds
  // checks).
  constexpr int kOpen = -1, kBlocked = -2;
  const int64_t pw = std::max(w, 0) + 2;
  std::vector<int> region(static_cast<size_t>(pw) * (std::max(h, 0) + 2), kBlocked);
  const std::vector<grid::CellState>& states = map.states();
  for (int y = 0; w > 0 && y < h; ++y) {
    const grid::CellState* row = &states[limits.FlatIndex({a.x, a.y + y})];
    int* out = &region[(y + 1) * pw + 1];
    for (int x = 0; x < w; ++x) out[x] = row[x] != grid::CellState::kOccupied ? kOpen : kBlocked;
  }
  int next = 0;
  // A stack, not a queue: the region is the same in any order, and a vector
  // reuses its memory from flood to flood.
  std::vector<int64_t> stack;
  const int64_t step[4] = {1, -1, pw, -pw};
  for (size_t i = 0; i < points.size(); ++i) {
    const grid::CellIndex c = limits.CellContaining(points[i]);
    const bool in_window = c.x >= a.x && c.y >= a.y && c.x <= b.x && c.y <= b.y;
    const int64_t at = in_window ? (c.y - a.y + 1) * pw + (c.x - a.x + 1) : 0;
    if (!in_window || region[at] == kBlocked) {
      label[i] = next++;
      continue;
    }
    if (region[at] == kOpen) {
      // Flood the seed's region once; later points in it just read the label.
      const int seed = next++;
      region[at] = seed;
      stack.push_back(at);
      while (!stack.empty()) {
        const int64_t u = stack.back();
        stack.pop_back();
        for (const int64_t d : step) {
          if (region[u + d] == kOpen) region[u + d] = seed, stack.push_back(u + d);
        }
      }
    }
    label[i] = region[at];
  }
  return label;
}

FrontierPartition PartitionFrontier(const PlanningMap& map,
                                    const std::vector<Eigen::Vector2d>& frontier,
                                    const NavigationPointOptions& options) {
  Validate(options);
  FrontierPartition partition;
  if (frontier.empty()) return partition;
  const MeanShiftClusters clusters = MeanShift(frontier, options.mean_shift);
  partition.points.resize(clusters.centres.size());
  for (size_t i = 0; i < frontier.size(); ++i) {
    partition.points[clusters.label[i]].push_back(frontier[i]);
  }
  for (const std::vector<Eigen::Vector2d>& points : partition.points) {
    partition.component.push_back(SplitByConnectivity(map, points, options.connectivity_margin_m));
    const std::vector<int>& component = partition.component.back();
    partition.num_components +=
        points.empty() ? 0 : *std::max_element(component.begin(), component.end()) + 1;
  }
  return partition;
}

std::vector<NavigationPoint> ComputeNavigationPoints(
    const PlanningMap& map, const PathDistanceField& distances,
    const std::vector<Eigen::Vector2d>& frontier, const Eigen::Vector2d& robot,
    const std::optional<Eigen::Vector2d>& current_goal, const NavigationPointOptions& options,
    NavigationPointStats* stats) {
  return ComputeNavigationPoints(map, distances, PartitionFrontier(map, frontier, options), robot,
                                 current_goal, options, stats);
}

std::vector<NavigationPoint> ComputeNavigationPoints(
    const PlanningMap& map, const PathDistanceField& distances, const FrontierPartition& partition,
    const Eigen::Vector2d& robot, const std::optional<Eigen::Vector2d>& current_goal,
    const NavigationPointOptions& options, NavigationPointStats* stats) {
  Validate(options);
  NavigationPointStats local_stats;
  NavigationPointStats& st = stats ? *stats : local_stats;
  st = {};
  std::vector<NavigationPoint> result;
  st.clusters = static_cast<int>(partition.points.size());
  st.components = partition.num_components;
  const double snap = map.options().goal_snap_radius_m;
  if (partition.reached_on != distances.id()) {
    partition.reached_on = distances.id();
    partition.reached.clear();
    for (const std::vector<Eigen::Vector2d>& points : partition.points) {
      partition.reached.emplace_back(points.size());
    }
  }
  for (size_t k = 0; k < partition.points.size(); ++k) {
    const std::vector<Eigen::Vector2d>& points = partition.points[k];
    const std::vector<int>& component = partition.component[k];
    const int num_components =
        points.empty() ? 0 : *std::max_element(component.begin(), component.end()) + 1;

    // Per component: its size and its point nearest to the robot by path.
    struct Best {
      int index = -1;
      double path = std::numeric_limits<double>::infinity();
      double straight = std::numeric_limits<double>::infinity();
      int size = 0;
      grid::CellIndex cell;
    };
    std::vector<Best> best(num_components);
    for (size_t i = 0; i < points.size(); ++i) {
      Best& b = best[component[i]];
      ++b.size;
      std::optional<PathDistanceField::Reached>& reached = partition.reached[k][i];
      if (!reached) reached = distances.NearestReached(points[i], snap);
      if (!reached) continue;
      const double straight = (points[i] - robot).norm();
      if (reached->distance_m < b.path ||
          (reached->distance_m == b.path && straight < b.straight)) {
        b = {static_cast<int>(i), reached->distance_m, straight, b.size, reached->cell};
      }
    }
    for (const Best& b : best) {
      if (b.index < 0) {
        ++st.unreachable_components;
        continue;
      }
      NavigationPoint np;
      np.position = points[b.index];
      np.cost_m = b.path;
      np.reached_cell = b.cell;
      np.info_gain_m2 = InfoGain(map, np.position, options);
      if (current_goal && (np.position - *current_goal).norm() <= options.hysteresis_radius_m) {
        np.info_gain_m2 *= options.hysteresis_gain;
      }
      np.revenue = options.info_multiplier * np.info_gain_m2 - np.cost_m;
      np.cluster = static_cast<int>(k);
      np.component_size = b.size;
      result.push_back(np);
    }
  }
  std::stable_sort(result.begin(), result.end(),
                   [](const NavigationPoint& a, const NavigationPoint& b) {
                     if (a.revenue != b.revenue) return a.revenue > b.revenue;
                     return a.cost_m < b.cost_m;
                   });
  return result;
}

}  // namespace scout::explore
