#include "scout/explore/failed_goal_memory.h"

#include <cmath>

#include "scout/explore/option_check.h"

namespace scout::explore {

void Validate(const FailedGoalOptions& o) {
  CheckAtLeast("failed_goals", "blacklist_radius_m", o.blacklist_radius_m, 0.0);
  CheckAtLeast("failed_goals", "retry_radius_m", o.retry_radius_m, 0.0);
  CheckAtLeast("failed_goals", "retry_known_area_change_m2", o.retry_known_area_change_m2, 0.0);
  CheckAtLeast("failed_goals", "max_failures", o.max_failures, 0.0);
}

double KnownAreaWithin(const PlanningMap& map, const Eigen::Vector2d& p, double radius_m) {
  int64_t known = 0;
  for (const grid::CellIndex& c : CellsWithin(map.limits(), p, radius_m)) {
    known += map.state(map.limits().FlatIndex(c)) != grid::CellState::kUnknown;
  }
  const double res = map.limits().resolution();
  return static_cast<double>(known) * res * res;
}

FailedGoalMemory::FailedGoalMemory(const FailedGoalOptions& options) : options_(options) {
  Validate(options_);
}

void FailedGoalMemory::RecordFailure(const Eigen::Vector2d& global,
                                     const std::vector<SubmapPose>& submaps,
                                     const PlanningMap& map) {
  const double known = KnownAreaWithin(map, global, options_.retry_radius_m);
  for (FailedGoal& g : goals_) {
    if ((Resolve(g.where, submaps) - global).norm() <= options_.blacklist_radius_m) {
      ++g.failures;
      g.blacklisted = true;
      g.known_area_m2 = known;
      return;
    }
  }
  goals_.push_back({Anchor(global, submaps), known, 1, true});
}

int FailedGoalMemory::RetryChangedGoals(const PlanningMap& map,
                                        const std::vector<SubmapPose>& submaps) {
  int lifted = 0;
  for (FailedGoal& g : goals_) {
    if (!g.blacklisted) continue;
    if (options_.max_failures > 0 && g.failures >= options_.max_failures) continue;
    const double known = KnownAreaWithin(map, Resolve(g.where, submaps), options_.retry_radius_m);
    if (std::abs(known - g.known_area_m2) > options_.retry_known_area_change_m2) {
      g.blacklisted = false;
      ++lifted;
    }
  }
  return lifted;
}

int FailedGoalMemory::RetryNear(const std::vector<Eigen::Vector2d>& points,
                                const std::vector<SubmapPose>& submaps) {
  int lifted = 0;
  for (FailedGoal& g : goals_) {
    if (!g.blacklisted) continue;
    if (options_.max_failures > 0 && g.failures >= options_.max_failures) continue;
    if (IsNear(Resolve(g.where, submaps), points)) {
      g.blacklisted = false;
      ++lifted;
    }
  }
  return lifted;
}

std::vector<Eigen::Vector2d> FailedGoalMemory::Blacklisted(
    const std::vector<SubmapPose>& submaps) const {
  std::vector<Eigen::Vector2d> out;
  for (const FailedGoal& g : goals_) {
    if (g.blacklisted) out.push_back(Resolve(g.where, submaps));
  }
  return out;
}

bool FailedGoalMemory::IsNear(const Eigen::Vector2d& global,
                              const std::vector<Eigen::Vector2d>& blacklisted) const {
  const double r2 = options_.blacklist_radius_m * options_.blacklist_radius_m;
  for (const Eigen::Vector2d& b : blacklisted) {
    if ((b - global).squaredNorm() <= r2) return true;
  }
  return false;
}

}  // namespace scout::explore
