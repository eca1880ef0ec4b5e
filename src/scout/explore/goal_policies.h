#ifndef SCOUT_EXPLORE_GOAL_POLICIES_H_
#define SCOUT_EXPLORE_GOAL_POLICIES_H_

#include <Eigen/Core>
#include <any>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scout/explore/navigation_points.h"
#include "scout/explore/path_distance_field.h"
#include "scout/explore/planning_map.h"

namespace scout::explore {

// What a policy sees when it picks goals.
struct PolicyInput {
  const PlanningMap* map = nullptr;
  // Path distances from the robot; set when the policy needs_path_distances().
  const PathDistanceField* distances = nullptr;
  // Global frontier points (after the exploration boundary), global frame.
  const std::vector<Eigen::Vector2d>* frontier = nullptr;
  Eigen::Vector2d robot = Eigen::Vector2d::Zero();
  // The goal being driven to, if any (for hysteresis).
  std::optional<Eigen::Vector2d> current_goal;
  // Blacklisted goals. The goal manager drops candidates within avoid_radius_m
  // of them; "scout" also drops such frontier points before clustering, so a
  // component whose nearest point failed offers its next point instead.
  const std::vector<Eigen::Vector2d>* avoid = nullptr;
  double avoid_radius_m = 0.0;
  // What the policy's Prepare returned for this input, if it ran.
  const std::any* prepared = nullptr;
};

struct GoalCandidate {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  // Higher is better; units are the policy's own.
  double score = 0.0;
};

// explore_lite's frontier cost (m-explore): cost = potential_scale · distance
// − gain_scale · size, lowest first; segments shorter than min_frontier_size_m
// are ignored. Distance is the straight line from the robot to the segment's
// nearest cell, size is the segment's cell count times the resolution.
struct ExploreLiteOptions {
  double potential_scale = 1e-3;
  double gain_scale = 1.0;
  double min_frontier_size_m = 0.5;
};

struct GoalPolicyOptions {
  // "scout" (navigation points) and "meanshift-centres" (its mean-shift,
  // information gain, multiplier and hysteresis).
  NavigationPointOptions navigation;
  ExploreLiteOptions explore_lite;
};

// Throws std::invalid_argument naming the key of a bad value.
void Validate(const GoalPolicyOptions& options);

// Turns the global frontier into ranked goals. The goal manager plans to them
// in order, so baselines may return goals the robot cannot reach (as the
// peers do); it blacklists those after planning fails.
class GoalPolicy {
 public:
  virtual ~GoalPolicy() = default;
  virtual std::string_view name() const = 0;
  virtual bool needs_path_distances() const { return false; }
  // True when the goal manager should pass over candidates whose path the
  // latest scan contradicts (GoalManagerOptions::scan_check_radius_m): part
  // of Scout's own goal choice; the baselines keep their published one.
  virtual bool checks_paths_against_scan() const { return false; }
  // True when the goal manager should stop where the robot keeps a margin
  // from unknown space (GoalManagerOptions::stand_off_unknown_margin_m):
  // likewise Scout's own.
  virtual bool keeps_stand_off_from_unknown() const { return false; }
  // The work of Rank that needs no path distances (input.distances unset),
  // which the goal manager runs while it computes them; Rank reads the result
  // from input.prepared and does the work itself without it. Must not
  // change the policy: it runs on another thread.
  virtual std::any Prepare(const PolicyInput& /*input*/) const { return {}; }
  // Returns goals, best first.
  virtual std::vector<GoalCandidate> Rank(const PolicyInput& input) const = 0;
  // For policies whose every candidate scores at most this much more than
  // minus its path distance (metres): a candidate beyond a path distance L
  // then scores below bound − L, so a ranking from a field settled to L
  // holds every candidate that can score more. Nothing when scores are not
  // bounded so (or need no path distances).
  virtual std::optional<double> ScoreAbovePathCost(const PlanningMap& /*map*/) const {
    return std::nullopt;
  }
};

// The selectable names: scout, nearest, explore-lite, meanshift-centres.
const std::vector<std::string>& GoalPolicyNames();

// Returns the policy called 'name':
// - scout: navigation points (ALGORITHMS §6), score = revenue.
// - nearest: Yamauchi; every frontier point by straight-line distance, nearest
//   first (score = −distance).
// - explore-lite: 8-connected segments of frontier cells, goal = segment
//   centroid even if it lies in a wall (as explore_lite does), score = −cost.
// - meanshift-centres: Umari; mean-shift cluster centres without the
//   connectivity split, revenue with straight-line cost.
// Throws std::invalid_argument on an unknown name or bad options.
std::unique_ptr<GoalPolicy> MakeGoalPolicy(std::string_view name, const GoalPolicyOptions& options);

// explore_lite-style segments, exposed for markers and tests.
struct FrontierSegment {
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  // Straight-line distance from the robot to the nearest cell, metres.
  double min_distance_m = 0.0;
  int cells = 0;
  double size_m = 0.0;
};
// Returns the 8-connected segments of the map cells holding frontier points
// (each cell counted once; points outside the map dropped), in order of their
// lowest row-major cell.
std::vector<FrontierSegment> FrontierSegments(const grid::MapLimits& limits,
                                              const std::vector<Eigen::Vector2d>& frontier,
                                              const Eigen::Vector2d& robot);

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_GOAL_POLICIES_H_
