#ifndef SCOUT_EXPLORE_GOAL_MANAGER_H_
#define SCOUT_EXPLORE_GOAL_MANAGER_H_

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "scout/explore/anchored_point.h"
#include "scout/explore/failed_goal_memory.h"
#include "scout/explore/goal_policies.h"
#include "scout/explore/path_follower.h"
#include "scout/explore/path_planner.h"
#include "scout/explore/planning_map.h"
#include "scout/geometry/rigid_transform.h"
#include "scout/grid/occupancy_map.h"

namespace scout::explore {

struct GoalManagerOptions {
  // A goal fails when the remaining path length has not shrunk by
  // progress_min_m within progress_timeout_s (explore_lite's 30 s).
  double progress_timeout_s = 30.0;
  double progress_min_m = 0.25;
  // While driving, a map change triggers re-selection (hysteresis keeps the
  // goal unless another is clearly better) and re-planning, at most this often.
  double replan_interval_s = 1.0;
  // Candidates planned to per selection before giving up until the next map
  // change (bounds the work when many baseline goals are unreachable).
  int max_plan_attempts = 10;
  // Exploration ends only after no goal was left for this long; at the start
  // the map may simply not have arrived yet.
  double finish_after_empty_s = 2.0;
  // After exploring, drive back to where Start() was called.
  bool return_to_start = false;
  // Optional exploration area: a simple polygon in the global frame (at least
  // three vertices); frontier points outside it are ignored. Empty: no limit.
  std::vector<Eigen::Vector2d> boundary;
  FailedGoalOptions failed_goals;
};

// Throws std::invalid_argument naming the key of a bad value.
void Validate(const GoalManagerOptions& options);

enum class ExploreState {
  kIdle,       // not started, or stopped: commands are zero
  kPlanning,   // choosing a goal and planning to it
  kDriving,    // following the path to the goal
  kReached,    // the goal was reached (one update; then kPlanning)
  kFailed,     // the goal failed (one update; then kPlanning)
  kReturning,  // driving back to the start
  kFinished,   // nothing left to explore (and back home, if asked)
};
std::string_view ToString(ExploreState state);

// One control cycle's view of the world.
struct ExploreInput {
  double time_s = 0.0;
  geometry::Rigid2d robot_pose;  // global frame
  // The fused global map and the global frontier points (global frame).
  const grid::OccupancyMap* map = nullptr;
  const std::vector<Eigen::Vector2d>* frontier = nullptr;
  // Current global poses of the submaps (empty: goals are kept globally).
  std::vector<SubmapPose> submaps;
  // True when the map or the frontier changed since the previous update.
  bool map_changed = false;
};

struct ExploreCounters {
  int goals_issued = 0;
  int goals_reached = 0;
  int goals_failed = 0;       // progress timeout
  int goals_unreachable = 0;  // no plan
  int goals_superseded = 0;   // another goal became better on the way
  int goals_retried = 0;      // lifted from the blacklist after a map change
  int selections = 0;
};

struct ExploreStatus {
  ExploreState state = ExploreState::kIdle;
  VelocityCommand command;
  std::optional<Eigen::Vector2d> goal;  // global
  std::vector<Eigen::Vector2d> path;    // global, for display
  std::vector<Eigen::Vector2d> blacklisted;
  bool returned_home = false;
};

// The exploration state machine: IDLE → PLANNING → DRIVING → REACHED/FAILED →
// PLANNING …, FINISHED when no goal is left (optionally via RETURNING).
// Owns the policy, the planner and the follower; the caller owns SLAM and
// the frontier, and applies the velocity commands.
class GoalManager {
 public:
  // Throws std::invalid_argument on bad options or a null policy.
  GoalManager(const GoalManagerOptions& options, const TraversabilityOptions& traversability,
              const PathPlannerOptions& planner, const PathFollowerOptions& follower,
              std::unique_ptr<GoalPolicy> policy);

  // Starts (or resumes) exploring at the next update; the first update after
  // the first Start() records home.
  void Start();
  // Stops: drops the goal and commands zero velocity until Start().
  void Stop();

  // Advances the state machine and returns the command for this cycle.
  ExploreStatus Update(const ExploreInput& input);

  ExploreState state() const { return state_; }
  const ExploreCounters& counters() const { return counters_; }
  const FailedGoalMemory& failed_goals() const { return failed_; }
  const GoalPolicy& policy() const { return *policy_; }

 private:
  struct Selection {
    std::optional<Eigen::Vector2d> goal;
    std::optional<PlannedPath> path;
    // No candidate outside the blacklist (as opposed to: plans failed).
    bool none_left = true;
  };
  // Builds the planning map when the map changed (or none exists yet) and
  // lifts the blacklisting of goals whose surroundings changed.
  void RefreshMap(const ExploreInput& input);
  // Returns the best goal that is not blacklisted and has a plan; goals
  // without a plan are blacklisted on the way.
  Selection SelectAndPlan(const ExploreInput& input);
  // Anchors the goal and hands its path to the follower. A re-plan to the
  // same goal keeps the progress clock running.
  void BeginDriving(const Eigen::Vector2d& goal, const PlannedPath& path, const ExploreInput& in,
                    ExploreState state, bool new_goal);
  void EndGoal(ExploreState next);
  // PLANNING: select and plan when something changed.
  void Plan(const ExploreInput& input);
  // No goal left: after finish_after_empty_s, return home or finish.
  void FinishOrGoHome(const ExploreInput& input);
  // DRIVING/RETURNING after a map change: re-select with hysteresis, re-plan.
  void Replan(const ExploreInput& input);
  // DRIVING/RETURNING: follow, watch progress.
  void Drive(const ExploreInput& input, ExploreStatus& status);
  std::vector<Eigen::Vector2d> FrontierInBoundary(const std::vector<Eigen::Vector2d>& f) const;

  GoalManagerOptions options_;
  TraversabilityOptions traversability_;
  PathPlanner planner_;
  PathFollower follower_;
  std::unique_ptr<GoalPolicy> policy_;
  FailedGoalMemory failed_;
  // Reached goals, kept out of selection until the map around them changes.
  FailedGoalMemory visited_;

  ExploreState state_ = ExploreState::kIdle;
  bool started_once_ = false;
  std::optional<AnchoredPoint> home_;
  std::optional<AnchoredPoint> goal_;
  std::unique_ptr<PlanningMap> map_;
  bool map_dirty_ = true;
  // PLANNING selects only after a map change or a goal ended, not every cycle.
  bool need_selection_ = true;
  double last_replan_s_ = -1e300;
  double best_remaining_m_ = 0.0;
  double last_progress_s_ = 0.0;
  std::optional<double> empty_since_s_;
  bool returned_home_ = false;
  ExploreCounters counters_;
};

// True when 'p' lies inside the simple polygon (even-odd rule).
bool InsidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p);

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_GOAL_MANAGER_H_
