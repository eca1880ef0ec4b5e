#include "scout/explore/path_follower.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "scout/explore/option_check.h"

namespace scout::explore {

void Validate(const PathFollowerOptions& o) {
  const std::string g = "path_follower";
  CheckAtLeast(g, "lookahead_m", o.lookahead_m, 0.0, /*strict=*/true);
  CheckAtLeast(g, "max_linear_speed_mps", o.max_linear_speed_mps, 0.0, /*strict=*/true);
  CheckAtLeast(g, "max_angular_speed_radps", o.max_angular_speed_radps, 0.0, /*strict=*/true);
  CheckAtLeast(g, "rotate_in_place_heading_rad", o.rotate_in_place_heading_rad, 0.0);
  if (o.rotate_in_place_heading_rad > M_PI) {
    RejectOption(g, "rotate_in_place_heading_rad", "at most pi", o.rotate_in_place_heading_rad);
  }
  CheckAtLeast(g, "rotate_gain_per_s", o.rotate_gain_per_s, 0.0, /*strict=*/true);
  CheckAtLeast(g, "goal_tolerance_m", o.goal_tolerance_m, 0.0, /*strict=*/true);
  CheckAtLeast(g, "slow_down_distance_m", o.slow_down_distance_m, 0.0);
  CheckAtLeast(g, "min_linear_speed_mps", o.min_linear_speed_mps, 0.0);
  if (o.min_linear_speed_mps > o.max_linear_speed_mps) {
    RejectOption(g, "min_linear_speed_mps", "at most max_linear_speed_mps", o.min_linear_speed_mps);
  }
}

PathFollower::PathFollower(const PathFollowerOptions& options) : options_(options) {
  Validate(options_);
}

void PathFollower::SetPath(std::vector<Eigen::Vector2d> path) {
  if (path.empty()) throw std::invalid_argument("PathFollower::SetPath: empty path");
  path_ = std::move(path);
  arc_.assign(path_.size(), 0.0);
  for (size_t i = 1; i < path_.size(); ++i) {
    arc_[i] = arc_[i - 1] + (path_[i] - path_[i - 1]).norm();
  }
  progress_m_ = 0.0;
}

Eigen::Vector2d PathFollower::PointAt(double s) const {
  if (s >= arc_.back()) return path_.back();
  const size_t i = std::upper_bound(arc_.begin(), arc_.end(), s) - arc_.begin();  // >= 1
  const double len = arc_[i] - arc_[i - 1];
  const double t = len > 0 ? (s - arc_[i - 1]) / len : 0.0;
  return path_[i - 1] + t * (path_[i] - path_[i - 1]);
}

double PathFollower::AdvanceProgress(const Eigen::Vector2d& p) {
  // Only segments a little ahead are candidates, so where the path passes
  // near itself the robot does not jump to a later part.
  const double horizon = progress_m_ + 2.0 * options_.lookahead_m + 0.5;
  double best_d = (p - PointAt(progress_m_)).norm();
  double best_s = progress_m_;
  for (size_t i = 1; i < path_.size() && arc_[i - 1] <= horizon; ++i) {
    if (arc_[i] < progress_m_) continue;
    const Eigen::Vector2d a = path_[i - 1], ab = path_[i] - path_[i - 1];
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    const double s = std::min(arc_[i - 1] + t * std::sqrt(len2), horizon);
    const double d = (p - PointAt(s)).norm();
    if (s >= progress_m_ && d < best_d) best_d = d, best_s = s;
  }
  progress_m_ = best_s;
  return best_d;
}

FollowStatus PathFollower::Update(const geometry::Rigid2d& pose) {
  FollowStatus status;
  if (path_.empty()) return status;
  const Eigen::Vector2d p = pose.translation();
  const double to_path = AdvanceProgress(p);
  status.remaining_m = arc_.back() - progress_m_ + to_path;
  const double to_goal = (path_.back() - p).norm();
  if (to_goal <= options_.goal_tolerance_m) {
    status.reached = true;
    status.remaining_m = to_goal;
    return status;
  }

  const Eigen::Vector2d target = PointAt(progress_m_ + options_.lookahead_m);
  const Eigen::Vector2d local = pose.inverse() * target;
  const double heading_error = std::atan2(local.y(), local.x());
  const double w_max = options_.max_angular_speed_radps;
  VelocityCommand& cmd = status.command;
  if (std::abs(heading_error) > options_.rotate_in_place_heading_rad) {
    cmd.angular_radps = std::clamp(options_.rotate_gain_per_s * heading_error, -w_max, w_max);
    return status;
  }
  // Pure pursuit: the arc through the robot and the target has curvature
  // 2 y / L² in the robot frame.
  const double l2 = std::max(local.squaredNorm(), 1e-9);
  const double curvature = 2.0 * local.y() / l2;
  double v = options_.max_linear_speed_mps;
  if (options_.slow_down_distance_m > 0.0) {
    v *= std::min(1.0, status.remaining_m / options_.slow_down_distance_m);
  }
  v = std::max(v, options_.min_linear_speed_mps);
  double w = curvature * v;
  if (std::abs(w) > w_max) {
    // Keep the arc, slow down along it.
    v *= w_max / std::abs(w);
    w = std::copysign(w_max, w);
  }
  cmd.linear_mps = v;
  cmd.angular_radps = w;
  return status;
}

}  // namespace scout::explore
