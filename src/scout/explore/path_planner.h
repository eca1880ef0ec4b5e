#ifndef SCOUT_EXPLORE_PATH_PLANNER_H_
#define SCOUT_EXPLORE_PATH_PLANNER_H_

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "scout/explore/planning_map.h"
#include "scout/explore/start_region.h"

namespace scout::explore {

struct PathPlannerOptions {
  // Optional penalty near obstacles: each metre travelled through a cell whose
  // clearance beyond the inflation radius is c costs an extra
  // clearance_weight · max(0, 1 − c / clearance_band_m) metres. 0 disables it
  // (plain shortest paths, equal to the navigation points' path costs).
  double clearance_weight = 0.0;
  double clearance_band_m = 0.5;
  // Replace runs of cells by straight segments with line of sight on the
  // inflated map. With a clearance penalty, a shortcut is taken only if its
  // penalised cost is no higher than that of the cells it replaces.
  bool shortcut = true;
};

// Throws std::invalid_argument naming the key of a bad value.
void Validate(const PathPlannerOptions& options);

// Returns the summed length of the segments between consecutive points.
double PolylineLength(const std::vector<Eigen::Vector2d>& points);

struct PlannedPath {
  // World points: the start, the corners kept by shortcutting, and the goal
  // (or the centre of the cell the goal was snapped to).
  std::vector<Eigen::Vector2d> points;
  // Length of the 8-connected cell path before shortcutting, metres.
  double cell_path_length_m = 0.0;
  // Length of 'points', metres.
  double length_m = 0.0;
  int expansions = 0;
};

// The cells plans from one start can reach on one map, learnt from a plan
// that failed: that search closed every one of them. A later plan from the
// same start on the same map to a goal none of whose cells is among them
// fails at once instead of searching them all again. Baseline goal policies
// rank goals that are often unreachable (centroids in walls, frontier points
// behind gaps), and each failed plan searched all of a museum's millions of
// cells (A* took a third of the CPU of a meanshift-centres museum run).
// Valid for one map and one start only.
class ReachableCells {
 public:
  bool known() const { return map_ != nullptr; }

 private:
  friend class PathPlanner;
  const PlanningMap* map_ = nullptr;
  const StartRegion* start_ = nullptr;
  std::vector<bool> cells_;  // flat index
};

// A* on a PlanningMap: 8-connected, octile heuristic, the same step rule as the
// path distance field, so every navigation point with a cost has a plan.
class PathPlanner {
 public:
  // Throws std::invalid_argument on bad options.
  explicit PathPlanner(const PathPlannerOptions& options);

  // Returns a path from 'start' to 'goal', or nothing when no traversable path
  // exists. A start in the inflated band leaves it as StartRegion says (over
  // cells where the bare disc fits); a goal whose cell is not traversable is
  // reached at a traversable cell within goal_snap_radius_m. With
  // clearance_weight > 0 the map must have clearance (else throws
  // std::invalid_argument).
  std::optional<PlannedPath> Plan(const PlanningMap& map, const Eigen::Vector2d& start,
                                  const Eigen::Vector2d& goal) const;
  // As above from the seeds of 'start' (which must come from 'map'): the same
  // start as a PathDistanceField built from it, so their costs agree.
  std::optional<PlannedPath> Plan(const PlanningMap& map, const StartRegion& start,
                                  const Eigen::Vector2d& goal) const;
  // As above; 'reachable' learns the reachable cells from the first plan
  // that fails and answers later plans from it (same result). Throws
  // std::invalid_argument when it was learnt on another map or start.
  std::optional<PlannedPath> Plan(const PlanningMap& map, const StartRegion& start,
                                  const Eigen::Vector2d& goal, ReachableCells& reachable) const;

  const PathPlannerOptions& options() const { return options_; }

 private:
  // Returns the points kept from 'raw' (cumulative A* costs 'cost', metres);
  // raw[0..first_free] are kept as they are.
  std::vector<Eigen::Vector2d> Shortcut(const PlanningMap& map,
                                        const std::vector<Eigen::Vector2d>& raw,
                                        const std::vector<double>& cost, size_t first_free) const;
  // Cost of the straight segment a-b: its length times the mean step factor of
  // the cells it passes through.
  double SegmentCost(const PlanningMap& map, const Eigen::Vector2d& a,
                     const Eigen::Vector2d& b) const;
  // 1 + the clearance penalty of a cell.
  float StepFactor(const PlanningMap& map, int64_t flat) const;
  std::optional<PlannedPath> Search(const PlanningMap& map, const StartRegion& start,
                                    const Eigen::Vector2d& goal, ReachableCells* reachable) const;

  PathPlannerOptions options_;
};

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_PATH_PLANNER_H_
