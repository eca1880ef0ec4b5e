#ifndef SCOUT_EXPLORE_NAVIGATION_POINTS_H_
#define SCOUT_EXPLORE_NAVIGATION_POINTS_H_

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "scout/explore/mean_shift.h"
#include "scout/explore/path_distance_field.h"
#include "scout/explore/planning_map.h"

namespace scout::explore {

// The longest info_visible_range_m: its rays cost range / (half a cell) steps
// each, 360 of them per navigation point.
inline constexpr double kMaxInfoVisibleRange_m = 20.0;

// Clustering with reachability and Umari-style revenue (ALGORITHMS §6).
struct NavigationPointOptions {
  MeanShiftOptions mean_shift;
  // The connectivity split looks for paths within this margin (metres) around
  // the bounding box of a cluster's points: "connected" means connected
  // nearby. A global flood fill would join every pair of frontiers the robot
  // reached, since the robot itself connects them.
  double connectivity_margin_m = 1.0;
  // info_gain = unknown area (m²) within this radius of the point.
  double info_radius_m = 1.0;
  // Cells outside the map are never observed: count them as unknown.
  bool outside_map_is_unknown = true;
  // > 0: info_gain = the unknown area a lidar at the point would see within
  // this range (m): rays every degree, blocked by occupied cells, unknown and
  // free cells let them through. 0: the disc of info_radius_m.
  double info_visible_range_m = 0.0;
  // revenue = info_multiplier · info_gain [m²] − path cost [m]. rrt_exploration
  // (and ALGORITHMS §6) use 3; with 1 a point of the most unknown area (π m²
  // at 1 m) is worth a detour of about 3 m instead of 9, so the robot leaves
  // fewer pockets behind to come back for (docs/EXPERIMENTS.md: office path to
  // 99 % 0.91 of what it was with 3; museum 1.02 and ucsd-atkinson-1f's SLAM
  // worse).
  double info_multiplier = 1.0;
  // Points within this radius (metres) of the current goal get their info gain
  // multiplied by hysteresis_gain, so the robot does not switch goals for a
  // marginally better one (rrt_exploration's defaults).
  double hysteresis_radius_m = 3.0;
  double hysteresis_gain = 2.0;
  // Scout's policy only: when at least 2, the best this many navigation points
  // (by revenue) are ranked by the shortest open tour that starts at the robot,
  // begins with the point and visits all of them (explore/tour.h), instead of
  // by revenue; the rest follow in revenue order. 0: off. At most 12.
  int tour_points = 0;
};

// Throws std::invalid_argument naming the key of a bad value.
void Validate(const NavigationPointOptions& options);

// A navigation point's information gain before hysteresis (m²): the unknown
// area seen from 'p' within options.info_visible_range_m when that is > 0,
// else the unknown area within options.info_radius_m.
double InfoGain(const PlanningMap& map, const Eigen::Vector2d& p,
                const NavigationPointOptions& options);

// The unknown area (m²) seen from 'p' within 'range_m' (see
// NavigationPointOptions::info_visible_range_m).
// An upper bound of InfoGain on a map of this resolution: the area of the
// square of cells it scans, or of the disc that holds the cells it counts.
double MaxInfoGainM2(double resolution_m, const NavigationPointOptions& options);
double UnknownAreaVisible(const PlanningMap& map, const Eigen::Vector2d& p, double range_m,
                          bool outside_map_is_unknown);

struct NavigationPoint {
  // One of the input frontier points (never a centroid), global frame.
  Eigen::Vector2d position;
  // Path distance from the robot over the inflated map, metres, to this
  // reached cell (within goal_snap_radius_m of the point).
  double cost_m = 0.0;
  grid::CellIndex reached_cell;
  // Unknown area around the point (after hysteresis), m².
  double info_gain_m2 = 0.0;
  double revenue = 0.0;
  // Index of the mean-shift cluster, and the frontier points in its component.
  int cluster = -1;
  int component_size = 0;
};

struct NavigationPointStats {
  int clusters = 0;
  // Components after the connectivity split, and those dropped because none
  // of their points has a path from the robot.
  int components = 0;
  int unreachable_components = 0;
};

// Returns one navigation point per reachable connected component of every
// mean-shift cluster of 'frontier', best revenue first. The navigation point of
// a component is its point with the least path distance from the robot (ties:
// nearer in a straight line, then input order); points without a path, i.e. no
// reached cell within goal_snap_radius_m, are never chosen, and a component
// without any reachable point yields nothing. 'distances' must come from
// 'map'. 'current_goal' enables hysteresis.
std::vector<NavigationPoint> ComputeNavigationPoints(
    const PlanningMap& map, const PathDistanceField& distances,
    const std::vector<Eigen::Vector2d>& frontier, const Eigen::Vector2d& robot,
    const std::optional<Eigen::Vector2d>& current_goal, const NavigationPointOptions& options,
    NavigationPointStats* stats = nullptr);

// The half of ComputeNavigationPoints that needs no path distances: the
// mean-shift clusters of a frontier and each cluster's points (in frontier
// order) with their connectivity components. The goal manager computes it
// while it computes the path distances.
struct FrontierPartition {
  std::vector<std::vector<Eigen::Vector2d>> points;  // per cluster
  std::vector<std::vector<int>> component;           // per cluster, per point
  int num_components = 0;
  // Each point's nearest reached cell as ComputeNavigationPoints found it on
  // the path distance field with id reached_on. A goal selection ranks one
  // partition several times on one field, settled farther each time; a cell
  // settled later lies farther than every cell settled before, so a point
  // once reached keeps its cell, and only the others are looked at again.
  mutable uint64_t reached_on = 0;
  mutable std::vector<std::vector<std::optional<PathDistanceField::Reached>>> reached;
};
FrontierPartition PartitionFrontier(const PlanningMap& map,
                                    const std::vector<Eigen::Vector2d>& frontier,
                                    const NavigationPointOptions& options);
// ComputeNavigationPoints on the partition of 'map''s frontier.
std::vector<NavigationPoint> ComputeNavigationPoints(
    const PlanningMap& map, const PathDistanceField& distances, const FrontierPartition& partition,
    const Eigen::Vector2d& robot, const std::optional<Eigen::Vector2d>& current_goal,
    const NavigationPointOptions& options, NavigationPointStats* stats = nullptr);

// Returns, for each point of one cluster, a component label (0, 1, ...) such
// that two points share a label iff a 4-connected path of non-occupied cells
// joins their cells within the window described above. A point whose cell is
// occupied or outside the map is a component of its own. 4-connectivity: a
// diagonal chain of occupied cells is a wall and must not leak.
std::vector<int> SplitByConnectivity(const PlanningMap& map,
                                     const std::vector<Eigen::Vector2d>& points, double margin_m);

// Returns the unknown area in m² of cells whose centres lie within 'radius_m'
// of 'p'.
double UnknownAreaWithin(const PlanningMap& map, const Eigen::Vector2d& p, double radius_m,
                         bool outside_map_is_unknown);

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_NAVIGATION_POINTS_H_
