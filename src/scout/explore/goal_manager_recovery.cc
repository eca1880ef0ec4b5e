#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <utility>
#include <vector>

#include "scout/explore/goal_manager.h"
#include "scout/geometry/segment.h"

// GoalManager's recovery from being stuck: backing up, driving back along the
// trail, the last resort, and the collision guard on those motions (one class
// with goal_manager.cc, split to keep each file readable at once).
namespace scout::explore {

bool GoalManager::BlockedBehind(const geometry::Rigid2d& pose) const {
  const double look_m = options_.back_up_look_behind_m;
  if (look_m <= 0.0 || !map_) return false;
  const double radius_m = map_->options().robot_radius_m;
  const geometry::Rigid2d robot_from_map = pose.inverse();
  // Nearest occupied cell centre to the robot now (any side), and to the
  // segment it would sweep backing up (rear half only).
  double now_m = std::numeric_limits<double>::infinity();
  double behind_m = now_m;
  ForEachCellWithin(map_->limits(), pose.translation(), radius_m + look_m,
                    [&](const grid::CellIndex& c) {
                      if (map_->state(map_->limits().FlatIndex(c)) != grid::CellState::kOccupied) {
                        return;
                      }
                      const Eigen::Vector2d q = robot_from_map * map_->limits().CellCenter(c);
                      now_m = std::min(now_m, q.norm());
                      if (q.x() >= 0.0) return;
                      const double along = std::max(q.x(), -look_m);
                      behind_m = std::min(behind_m, (q - Eigen::Vector2d(along, 0.0)).norm());
                    });
  // Blocked when backing up would bring the disc onto a mapped obstacle.
  // Where the map has the disc on one already (the map's error: the robot
  // stands there), backing along it makes nothing worse: then only coming
  // closer to one by more than half the look-behind blocks. That exception
  // is not for a disc the map has clear: an obstacle beside and behind the
  // robot comes closer by less than that, and the robot backed into one
  // (willow-garage seed 2 with the visible gain, at 1970.85 s).
  const bool clear_now = now_m >= radius_m;
  return (behind_m < radius_m && (clear_now || behind_m < now_m - 0.5 * look_m)) || OffTrail(pose);
}

bool GoalManager::GuardRear(const ExploreInput& in, VelocityCommand* command) const {
  if (!in.recent_returns || options_.guard.memory_s <= 0.0) return false;
  const GuardedCommand g =
      GuardBackward(*command, in.recent_returns(), map_->options().robot_radius_m, options_.guard);
  *command = g.command;
  return g.stopped;
}

bool GoalManager::OffTrail(const geometry::Rigid2d& pose) const {
  const double look_m = options_.back_up_look_behind_m;
  const std::deque<Eigen::Vector2d>& trail = trail_.points();
  if (look_m <= 0.0 || trail.empty()) return false;
  const Eigen::Vector2d back(-std::cos(pose.theta()), -std::sin(pose.theta()));
  // Centres every trail step along the segment, its far end included.
  const int steps = static_cast<int>(std::ceil(look_m / Trail::kStep_m));
  for (int k = 1; k <= steps; ++k) {
    const Eigen::Vector2d c = pose.translation() + (look_m * k / steps) * back;
    double nearest_m = (c - trail.front()).norm();
    for (size_t i = 1; i < trail.size(); ++i) {
      nearest_m = std::min(nearest_m, geometry::DistanceToSegment(c, trail[i - 1], trail[i]));
    }
    if (nearest_m > options_.back_up_trail_tolerance_m) return true;
  }
  return false;
}

void GoalManager::EndStuckGoal(const ExploreInput& in) {
  if (state_ == ExploreState::kReturning) return FailGoal(in);
  if (!goal_) return EndGoal(ExploreState::kPlanning, GoalOutcome::kOpen);  // a drive back
  std::vector<Eigen::Vector2d> stuck_before;
  for (const AnchoredPoint& p : stuck_goals_) stuck_before.push_back(Resolve(p, in.submaps));
  if (failed_.IsNear(Resolve(*goal_, in.submaps), stuck_before)) return FailGoal(in);
  stuck_goals_.push_back(*goal_);
  ++counters_.stuck_reselections;
  EndGoal(ExploreState::kPlanning, GoalOutcome::kStuck);
}

void GoalManager::Guard(const ExploreInput& in, VelocityCommand* command, double clearance_m) {
  if (!in.obstacles) return;
  CollisionGuardOptions guard = options_.guard;
  guard.clearance_m = std::min(guard.clearance_m, clearance_m);
  const GuardedCommand g =
      GuardCommand(*command, *in.obstacles, map_->options().robot_radius_m, guard,
                   follower_.options().max_angular_speed_radps, in.base ? &*in.base : nullptr);
  *command = g.command;
  counters_.guard_steers += g.steered;
  if (g.stopped && !guard_stopped_) ++counters_.guard_stops;
  guard_stopped_ = g.stopped;
}

void GoalManager::EndRecovery(const ExploreInput& in, const Eigen::Vector2d& from) {
  moving_since_.reset();
  if (options_.close_stuck_passage_radius_m > 0.0) {
    // The passage closes with the next planning map (built by the
    // selection FailGoal leads to).
    stuck_places_.RecordFailure(from, in.submaps, *map_);
    map_dirty_ = true;
  }
  EndStuckGoal(in);
}

bool GoalManager::StartRetrace(const ExploreInput& in) {
  // Only a way back that leads at least a back-up's length away is worth
  // leaving the goal's path for.
  if (options_.retrace_m <= 0.0 || retrace_trail_.empty() ||
      (retrace_trail_.points().front() - in.robot_pose.translation()).norm() <
          options_.back_up_distance_m) {
    return false;
  }
  ++counters_.retraces;
  // The goal's path is given up; the goal ends when the retrace does.
  BeginDriveBack(in, retrace_trail_.Reversed(in.robot_pose.translation()));
  return true;
}

void GoalManager::BeginDriveBack(const ExploreInput& in, std::vector<Eigen::Vector2d> way) {
  moving_since_.reset();
  retracing_since_ = {in.time_s, in.robot_pose.translation()};
  follower_.SetPath(std::move(way));
}

bool GoalManager::LastResort(const ExploreInput& in, bool drive_back) {
  if (options_.last_resort_retrace_m <= 0.0 ||
      counters_.last_resorts >= options_.max_last_resorts) {
    return false;
  }
  // Out by itself, or in a recovery already (a back-up or a drive back): it
  // goes on with what it does.
  if (!drive_back || backing_up_since_ || retracing_since_) {
    ++counters_.last_resorts;
    return true;
  }
  // A goal that just ended (reached, failed) leaves the state machine about
  // to select afresh, as in planning.
  if (!in.driven || state_ == ExploreState::kIdle || state_ == ExploreState::kFinished ||
      state_ == ExploreState::kReturning) {
    return false;
  }
  std::vector<Eigen::Vector2d> way =
      WayBack(*in.driven, in.robot_pose.translation(), options_.last_resort_retrace_m);
  if (way.empty()) return false;
  ++counters_.last_resorts;
  // The goal it could not reach in all that time fails; the drive back ends
  // as a retrace does, with a selection afresh (EndStuckGoal without a goal).
  if (goal_ && map_) {
    ++counters_.goals_failed;
    failed_.RecordFailure(Resolve(*goal_, in.submaps), in.submaps, *map_);
  }
  EndGoal(ExploreState::kDriving, GoalOutcome::kFailed);
  BeginDriveBack(in, std::move(way));
  return true;
}

void GoalManager::Retrace(const ExploreInput& in, ExploreStatus& status) {
  const Eigen::Vector2d from = retracing_since_->second;
  const FollowStatus fs = follower_.Update(in.robot_pose);
  // Stuck on the way back too (the same rule as on a goal's path): it ends
  // like a back-up that could go no farther.
  const bool stuck = StuckTimedOut(in.time_s);
  const bool too_long = in.time_s - retracing_since_->first > options_.progress_timeout_s;
  if (fs.reached || stuck || too_long) {
    retracing_since_.reset();
    retrace_trail_.Clear();
    return EndRecovery(in, from);
  }
  status.command = fs.command;
  Guard(in, &status.command, options_.retrace_clearance_m);
  // Turning to face the way back is not being stuck. The guard passes
  // commands that are not forward unchanged. Being stuck ends the retrace at
  // the next update (above).
  StuckAfterMotion(fs.command.linear_mps > 0.0, in);
}

bool GoalManager::StuckAfterMotion(bool forward, const ExploreInput& in) {
  const Eigen::Vector2d here = in.robot_pose.translation();
  if (!forward) {
    moving_since_.reset();
  } else if (!moving_since_ ||
             (here - moving_since_->second).norm() >= options_.stuck_min_motion_m) {
    moving_since_ = {in.time_s, here};
  } else {
    return StuckTimedOut(in.time_s);
  }
  return false;
}

bool GoalManager::StuckTimedOut(double time_s) const {
  return moving_since_ && options_.stuck_timeout_s > 0.0 &&
         time_s - moving_since_->first >= options_.stuck_timeout_s;
}

}  // namespace scout::explore
