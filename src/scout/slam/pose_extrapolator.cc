#include "scout/slam/pose_extrapolator.h"

#include <algorithm>
#include <cmath>

namespace scout::slam {
namespace {

// Odometry that stopped arriving says nothing about the motion since: beyond
// this, the constant-velocity model of the matched poses takes over.
constexpr double kMaxOdometryExtensionS = 0.5;
// About 20 s of 50 Hz odometry.
constexpr size_t kMaxOdometryBeforeFirstPose = 1000;
// The constant-velocity model is extended at most this long past the last
// matched pose (or twice the interval between the two poses, if longer, so
// sparse logs without odometry keep their prediction); then the predicted
// pose stops moving. A scan stamped far after the rest (a corrupt time of
// 1e6 s) would otherwise be predicted thousands of kilometres away.
constexpr double kMaxConstantVelocityExtensionS = 2.0;

bool IsFinite(const geometry::Rigid2d& pose) {
  return pose.translation().allFinite() && std::isfinite(pose.theta());
}

}  // namespace

geometry::Rigid2d InterpolatePose(const geometry::Rigid2d& a, const geometry::Rigid2d& b,
                                  double f) {
  const double turn = geometry::NormalizeAngle(b.theta() - a.theta());
  return geometry::Rigid2d(a.translation() + f * (b.translation() - a.translation()),
                           a.theta() + f * turn);
}

void PoseExtrapolator::AddPose(double time_s, const geometry::Rigid2d& pose) {
  if (!std::isfinite(time_s) || !IsFinite(pose)) return;
  if (!poses_.empty() && time_s < poses_.back().time_s) return;
  poses_.push_back({time_s, pose});
  while (poses_.size() > 2) poses_.pop_front();
  TrimOdometry();
}

void PoseExtrapolator::AddOdometry(const sensor::Odometry& odometry) {
  if (!std::isfinite(odometry.time_s) || !IsFinite(odometry.pose)) return;
  if (!odometry_.empty() && odometry.time_s <= odometry_.back().time_s) return;
  odometry_.push_back(odometry);
  TrimOdometry();
}

void PoseExtrapolator::TrimOdometry() {
  // Keep the last reading at or before the newest pose (needed to interpolate
  // at its time) and everything after it; always keep two for the velocity.
  if (poses_.empty()) {
    // The first scan may be older than the newest readings: keep a bounded
    // history rather than only the last pair.
    while (odometry_.size() > kMaxOdometryBeforeFirstPose) odometry_.pop_front();
    return;
  }
  const double since = poses_.back().time_s;
  while (odometry_.size() > 2 && odometry_[1].time_s <= since) odometry_.pop_front();
}

std::optional<double> PoseExtrapolator::last_pose_time() const {
  if (poses_.empty()) return std::nullopt;
  return poses_.back().time_s;
}

std::optional<geometry::Rigid2d> PoseExtrapolator::OdometryAt(double time_s) const {
  if (odometry_.size() < 2 || time_s < odometry_.front().time_s) return std::nullopt;
  // Find the bracketing pair; past the newest reading, extend the last pair.
  size_t i = 1;
  while (i + 1 < odometry_.size() && odometry_[i].time_s < time_s) ++i;
  const sensor::Odometry& a = odometry_[i - 1];
  const sensor::Odometry& b = odometry_[i];
  const double f = (time_s - a.time_s) / (b.time_s - a.time_s);
  // The velocity is constant in the robot frame (a constant twist), so
  // extrapolate the relative motion rather than the odometry-frame position.
  if (f <= 1.0) return InterpolatePose(a.pose, b.pose, f);
  if (time_s - b.time_s > kMaxOdometryExtensionS) return std::nullopt;
  const geometry::Rigid2d step = a.pose.inverse() * b.pose;
  return a.pose * InterpolatePose(geometry::Rigid2d(), step, f);
}

geometry::Rigid2d PoseExtrapolator::ExtrapolatePose(double time_s) const {
  if (poses_.empty()) return geometry::Rigid2d();
  const TimedPose& last = poses_.back();
  const std::optional<geometry::Rigid2d> odom_then = OdometryAt(last.time_s);
  const std::optional<geometry::Rigid2d> odom_now = OdometryAt(time_s);
  if (odom_then.has_value() && odom_now.has_value()) {
    return last.pose * (odom_then->inverse() * *odom_now);
  }
  if (poses_.size() < 2 || !(last.time_s > poses_.front().time_s)) return last.pose;
  // Constant velocity in the robot frame, from the last two matched poses.
  const TimedPose& before = poses_.front();
  const double interval_s = last.time_s - before.time_s;
  const double extension_s =
      std::min(time_s - last.time_s, std::max(kMaxConstantVelocityExtensionS, 2.0 * interval_s));
  const double f = (last.time_s + extension_s - before.time_s) / interval_s;
  const geometry::Rigid2d step = before.pose.inverse() * last.pose;
  return before.pose * InterpolatePose(geometry::Rigid2d(), step, f);
}

}  // namespace scout::slam
