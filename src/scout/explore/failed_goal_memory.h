#ifndef SCOUT_EXPLORE_FAILED_GOAL_MEMORY_H_
#define SCOUT_EXPLORE_FAILED_GOAL_MEMORY_H_

#include <Eigen/Core>
#include <vector>

#include "scout/explore/anchored_point.h"
#include "scout/explore/planning_map.h"

namespace scout::explore {

struct FailedGoalOptions {
  // Goals within this distance (metres) of a blacklisted goal are skipped.
  double blacklist_radius_m = 0.5;
  // A blacklisted goal is retried once the known area (free or occupied)
  // within retry_radius_m of it has changed by more than this many m²: the map
  // there changed, so the reason it failed may be gone.
  double retry_radius_m = 1.0;
  double retry_known_area_change_m2 = 0.25;
  // After this many failures a goal is never retried (0: always retried), so
  // a place that keeps failing cannot trap the robot in a loop.
  int max_failures = 3;
};

// Throws std::invalid_argument naming the key of a bad value.
void Validate(const FailedGoalOptions& options);

struct FailedGoal {
  AnchoredPoint where;
  // Known area around the goal when it last failed, m².
  double known_area_m2 = 0.0;
  int failures = 0;
  bool blacklisted = true;
};

// Failed goals kept in submap-local coordinates, so they stay on their place
// in the map through loop closures, and retried when the map around them
// changes.
class FailedGoalMemory {
 public:
  // Throws std::invalid_argument on bad options.
  explicit FailedGoalMemory(const FailedGoalOptions& options);

  // Records a failure at 'global'; a remembered goal within the blacklist
  // radius counts it (one more failure) instead of a new entry.
  void RecordFailure(const Eigen::Vector2d& global, const std::vector<SubmapPose>& submaps,
                     const PlanningMap& map);
  // Lifts the blacklisting of goals whose surroundings changed (see options);
  // returns how many were lifted.
  int RetryChangedGoals(const PlanningMap& map, const std::vector<SubmapPose>& submaps);
  // Lifts the blacklisting of goals (below max_failures) within the blacklist
  // radius of one of 'points' (global), whatever the map did; returns how
  // many were lifted.
  int RetryNear(const std::vector<Eigen::Vector2d>& points, const std::vector<SubmapPose>& submaps);
  // Returns the global positions of the blacklisted goals.
  std::vector<Eigen::Vector2d> Blacklisted(const std::vector<SubmapPose>& submaps) const;
  // True when 'global' lies within the blacklist radius of one of 'blacklisted'.
  bool IsNear(const Eigen::Vector2d& global, const std::vector<Eigen::Vector2d>& blacklisted) const;

  const std::vector<FailedGoal>& goals() const { return goals_; }
  const FailedGoalOptions& options() const { return options_; }

 private:
  FailedGoalOptions options_;
  std::vector<FailedGoal> goals_;
};

// Returns the area in m² of known (free or occupied) cells whose centres lie
// within 'radius_m' of 'p'.
double KnownAreaWithin(const PlanningMap& map, const Eigen::Vector2d& p, double radius_m);

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_FAILED_GOAL_MEMORY_H_
