#include "scout/explore/goal_manager.h"

#include <stdexcept>
#include <utility>

#include "scout/explore/option_check.h"

namespace scout::explore {

void Validate(const GoalManagerOptions& o) {
  const std::string g = "goal_manager";
  CheckAtLeast(g, "progress_timeout_s", o.progress_timeout_s, 0.0, /*strict=*/true);
  CheckAtLeast(g, "progress_min_m", o.progress_min_m, 0.0);
  CheckAtLeast(g, "replan_interval_s", o.replan_interval_s, 0.0);
  CheckAtLeast(g, "max_plan_attempts", o.max_plan_attempts, 1.0);
  CheckAtLeast(g, "finish_after_empty_s", o.finish_after_empty_s, 0.0);
  if (!o.boundary.empty() && o.boundary.size() < 3) {
    RejectOption(g, "boundary", "no vertices or at least 3 vertices",
                 static_cast<double>(o.boundary.size()));
  }
  for (const Eigen::Vector2d& v : o.boundary) {
    if (!v.allFinite()) RejectOption(g, "boundary", "finite vertices", v.x() + v.y());
  }
  Validate(o.failed_goals);
}

std::string_view ToString(ExploreState state) {
  switch (state) {
    case ExploreState::kIdle:
      return "idle";
    case ExploreState::kPlanning:
      return "planning";
    case ExploreState::kDriving:
      return "driving";
    case ExploreState::kReached:
      return "reached";
    case ExploreState::kFailed:
      return "failed";
    case ExploreState::kReturning:
      return "returning";
    case ExploreState::kFinished:
      return "finished";
  }
  return "unknown";
}

bool InsidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p) {
  bool inside = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

GoalManager::GoalManager(const GoalManagerOptions& options,
                         const TraversabilityOptions& traversability,
                         const PathPlannerOptions& planner, const PathFollowerOptions& follower,
                         std::unique_ptr<GoalPolicy> policy)
    : options_(options),
      traversability_(traversability),
      planner_(planner),
      follower_(follower),
      policy_(std::move(policy)),
      failed_(options.failed_goals),
      visited_(options.failed_goals) {
  Validate(options_);
  Validate(traversability_);
  if (!policy_) throw std::invalid_argument("GoalManager: no goal policy");
}

void GoalManager::Start() {
  if (state_ == ExploreState::kIdle || state_ == ExploreState::kFinished) {
    state_ = ExploreState::kPlanning;
    need_selection_ = true;
    empty_since_s_.reset();
  }
}

void GoalManager::Stop() {
  state_ = ExploreState::kIdle;
  goal_.reset();
  follower_.Clear();
}

std::vector<Eigen::Vector2d> GoalManager::FrontierInBoundary(
    const std::vector<Eigen::Vector2d>& frontier) const {
  if (options_.boundary.empty()) return frontier;
  std::vector<Eigen::Vector2d> inside;
  for (const Eigen::Vector2d& p : frontier) {
    if (InsidePolygon(options_.boundary, p)) inside.push_back(p);
  }
  return inside;
}

void GoalManager::RefreshMap(const ExploreInput& in) {
  if (map_ && !map_dirty_) return;
  map_ = std::make_unique<PlanningMap>(*in.map, traversability_,
                                       planner_.options().clearance_weight > 0.0);
  map_dirty_ = false;
  counters_.goals_retried += failed_.RetryChangedGoals(*map_, in.submaps);
  visited_.RetryChangedGoals(*map_, in.submaps);
}

GoalManager::Selection GoalManager::SelectAndPlan(const ExploreInput& in) {
  ++counters_.selections;
  const std::vector<Eigen::Vector2d> frontier = FrontierInBoundary(*in.frontier);
  const Eigen::Vector2d robot = in.robot_pose.translation();
  std::optional<PathDistanceField> field;
  if (policy_->needs_path_distances()) field.emplace(*map_, robot);
  PolicyInput pi;
  pi.map = map_.get();
  pi.distances = field ? &*field : nullptr;
  pi.frontier = &frontier;
  pi.robot = robot;
  if (goal_) pi.current_goal = Resolve(*goal_, in.submaps);
  // Reached goals are avoided like failed ones until the map around them
  // changes: a frontier that stays after arrival cannot be seen from there.
  std::vector<Eigen::Vector2d> blacklisted = failed_.Blacklisted(in.submaps);
  const std::vector<Eigen::Vector2d> visited = visited_.Blacklisted(in.submaps);
  blacklisted.insert(blacklisted.end(), visited.begin(), visited.end());
  pi.avoid = &blacklisted;
  pi.avoid_radius_m = options_.failed_goals.blacklist_radius_m;

  Selection sel;
  int attempts = 0;
  for (const GoalCandidate& c : policy_->Rank(pi)) {
    if (failed_.IsNear(c.position, blacklisted)) continue;
    sel.none_left = false;
    if (attempts++ >= options_.max_plan_attempts) break;
    std::optional<PlannedPath> path = planner_.Plan(*map_, robot, c.position);
    if (!path) {
      ++counters_.goals_unreachable;
      failed_.RecordFailure(c.position, in.submaps, *map_);
      blacklisted.push_back(c.position);
      continue;
    }
    sel.goal = c.position;
    sel.path = std::move(path);
    break;
  }
  return sel;
}

void GoalManager::BeginDriving(const Eigen::Vector2d& goal, const PlannedPath& path,
                               const ExploreInput& in, ExploreState state, bool new_goal) {
  goal_ = Anchor(goal, in.submaps);
  follower_.SetPath(path.points);
  best_remaining_m_ = path.length_m;
  last_replan_s_ = in.time_s;
  if (new_goal) {
    last_progress_s_ = in.time_s;
    if (state == ExploreState::kDriving) ++counters_.goals_issued;
  }
  state_ = state;
}

void GoalManager::EndGoal(ExploreState next) {
  goal_.reset();
  follower_.Clear();
  state_ = next;
  need_selection_ = true;
}

void GoalManager::Plan(const ExploreInput& in) {
  RefreshMap(in);
  if (!need_selection_) return;  // nothing changed since the last empty selection
  Selection sel = SelectAndPlan(in);
  if (sel.goal) {
    empty_since_s_.reset();
    BeginDriving(*sel.goal, *sel.path, in, ExploreState::kDriving, /*new_goal=*/true);
    return;
  }
  // Candidates left whose plans were not tried yet: go on next cycle.
  need_selection_ = !sel.none_left;
  if (!sel.none_left) empty_since_s_.reset();
}

void GoalManager::FinishOrGoHome(const ExploreInput& in) {
  if (!empty_since_s_) empty_since_s_ = in.time_s;
  if (in.time_s - *empty_since_s_ < options_.finish_after_empty_s) return;
  if (options_.return_to_start && home_) {
    const Eigen::Vector2d home = Resolve(*home_, in.submaps);
    if ((home - in.robot_pose.translation()).norm() <= follower_.options().goal_tolerance_m) {
      returned_home_ = true;
    } else if (auto path = planner_.Plan(*map_, in.robot_pose.translation(), home)) {
      BeginDriving(home, *path, in, ExploreState::kReturning, /*new_goal=*/true);
      return;
    }
  }
  EndGoal(ExploreState::kFinished);
}

void GoalManager::Replan(const ExploreInput& in) {
  RefreshMap(in);
  last_replan_s_ = in.time_s;
  if (state_ == ExploreState::kReturning) {
    // Home moves with its submap; a failed re-plan keeps the old path.
    if (auto path =
            planner_.Plan(*map_, in.robot_pose.translation(), Resolve(*home_, in.submaps))) {
      BeginDriving(Resolve(*home_, in.submaps), *path, in, state_, /*new_goal=*/false);
    }
    return;
  }
  const Eigen::Vector2d current = Resolve(*goal_, in.submaps);
  Selection sel = SelectAndPlan(in);
  if (sel.goal) {
    const bool same = (*sel.goal - current).norm() <= follower_.options().goal_tolerance_m;
    if (!same) ++counters_.goals_superseded;
    BeginDriving(*sel.goal, *sel.path, in, ExploreState::kDriving, /*new_goal=*/!same);
  } else if (sel.none_left) {
    // The goal's frontier has been seen meanwhile and nothing else is left.
    ++counters_.goals_superseded;
    EndGoal(ExploreState::kPlanning);
  }
}

void GoalManager::Drive(const ExploreInput& in, ExploreStatus& status) {
  if (map_dirty_ && in.time_s - last_replan_s_ >= options_.replan_interval_s) {
    Replan(in);
    if (state_ != ExploreState::kDriving && state_ != ExploreState::kReturning) return;
  }
  const bool returning = state_ == ExploreState::kReturning;
  const FollowStatus fs = follower_.Update(in.robot_pose);
  if (fs.reached) {
    if (returning) {
      returned_home_ = true;
      EndGoal(ExploreState::kFinished);
    } else {
      ++counters_.goals_reached;
      visited_.RecordFailure(Resolve(*goal_, in.submaps), in.submaps, *map_);
      EndGoal(ExploreState::kReached);
    }
    return;
  }
  if (fs.remaining_m < best_remaining_m_ - options_.progress_min_m) {
    best_remaining_m_ = fs.remaining_m;
    last_progress_s_ = in.time_s;
  }
  if (in.time_s - last_progress_s_ > options_.progress_timeout_s) {
    if (returning) {
      EndGoal(ExploreState::kFinished);
    } else {
      ++counters_.goals_failed;
      failed_.RecordFailure(Resolve(*goal_, in.submaps), in.submaps, *map_);
      EndGoal(ExploreState::kFailed);
    }
    return;
  }
  status.command = fs.command;
}

ExploreStatus GoalManager::Update(const ExploreInput& in) {
  if (!in.map || !in.frontier) throw std::invalid_argument("GoalManager::Update: no map/frontier");
  if (in.map_changed) {
    map_dirty_ = true;
    need_selection_ = true;
  }
  ExploreStatus status;
  if (state_ != ExploreState::kIdle && state_ != ExploreState::kFinished) {
    if (!home_) home_ = Anchor(in.robot_pose.translation(), in.submaps);
    if (state_ == ExploreState::kReached || state_ == ExploreState::kFailed) {
      state_ = ExploreState::kPlanning;
    }
    if (state_ == ExploreState::kPlanning) {
      Plan(in);
      if (state_ == ExploreState::kPlanning && !need_selection_) FinishOrGoHome(in);
    }
    if (state_ == ExploreState::kDriving || state_ == ExploreState::kReturning) {
      Drive(in, status);
    }
  }
  status.state = state_;
  if (goal_) status.goal = Resolve(*goal_, in.submaps);
  if (follower_.has_path()) status.path = follower_.path();
  status.blacklisted = failed_.Blacklisted(in.submaps);
  status.returned_home = returned_home_;
  return status;
}

}  // namespace scout::explore
