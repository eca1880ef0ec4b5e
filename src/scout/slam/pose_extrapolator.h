#ifndef SCOUT_SLAM_POSE_EXTRAPOLATOR_H_
#define SCOUT_SLAM_POSE_EXTRAPOLATOR_H_

#include <deque>
#include <optional>

#include "scout/geometry/rigid_transform.h"
#include "scout/sensor/odometry.h"

namespace scout::slam {

// Predicts the robot pose (local SLAM frame) at a scan's time, as the initial
// estimate of scan matching. With odometry covering the time since the last
// scan-matched pose, the prediction is that pose composed with the odometry
// delta between the two times (odometry interpolated at both times; up to
// 0.5 s beyond the newest reading, the odometry's last velocity is extended).
// Otherwise, a constant-velocity model from the last two matched poses,
// extended at most max(2 s, twice their interval) past the newer one.
// Motion between samples is interpolated linearly in (x, y, theta) of the
// robot frame, which is exact for straight lines and close for short arcs.
class PoseExtrapolator {
 public:
  // Records the scan-matched pose at 'time_s'. Poses older than the newest one
  // are ignored (scans arrive in time order).
  void AddPose(double time_s, const geometry::Rigid2d& pose);
  // Records an odometry reading. Readings older than the newest one, or with a
  // non-finite pose or time, are ignored.
  void AddOdometry(const sensor::Odometry& odometry);

  // Returns the predicted pose at 'time_s'; the identity before any pose.
  geometry::Rigid2d ExtrapolatePose(double time_s) const;

  // Returns the odometry pose interpolated at 'time_s' if readings bracket it
  // or the last velocity can extend them to it; nullopt otherwise.
  std::optional<geometry::Rigid2d> OdometryAt(double time_s) const;

  std::optional<double> last_pose_time() const;

 private:
  struct TimedPose {
    double time_s;
    geometry::Rigid2d pose;
  };
  void TrimOdometry();

  // The newest two matched poses (oldest first).
  std::deque<TimedPose> poses_;
  // Odometry readings from just before the newest matched pose onwards.
  std::deque<sensor::Odometry> odometry_;
};

// Returns the pose a fraction 'f' of the way from 'a' to 'b' (translation
// linearly, rotation along the shorter arc); f outside [0, 1] extrapolates.
geometry::Rigid2d InterpolatePose(const geometry::Rigid2d& a, const geometry::Rigid2d& b, double f);

}  // namespace scout::slam

#endif  // SCOUT_SLAM_POSE_EXTRAPOLATOR_H_
