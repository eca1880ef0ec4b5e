#ifndef SCOUT_SYNTHETIC_SCAN_POSES_H_
#define SCOUT_SYNTHETIC_SCAN_POSES_H_

#include <Eigen/Core>
#include <vector>

#include "scout/geometry/rigid_transform.h"

namespace scout::synthetic {

// Where and when the robot takes a scan.
struct ScanPose {
  geometry::Rigid2d pose;  // true pose, world frame
  double time_s = 0.0;
  double travelled_m = 0.0;  // path length driven so far
};

// The robot's motion along a tour and its motion filter (ALGORITHMS §7).
struct MotionOptions {
  // A scan is taken whenever the robot has moved this far...
  double scan_spacing_m = 0.2;
  // ...or turned this much since the previous scan.
  double scan_spacing_rad = 0.017453292519943295;  // 1 degree
  // Speeds, used only for the scans' time stamps.
  double linear_speed_mps = 0.5;
  double angular_speed_radps = 0.5;
};

// Returns the scan poses of a robot driving 'tour': it starts at the first
// point facing along the first segment and takes a scan there; at every
// point it turns on the spot to face the next segment, then drives straight
// along it. Scans are taken exactly where the motion filter triggers (no
// interpolation error). Stops after 'max_scans' scans when it is positive.
std::vector<ScanPose> SampleScanPoses(const std::vector<Eigen::Vector2d>& tour,
                                      const MotionOptions& options, int max_scans);

}  // namespace scout::synthetic

#endif  // SCOUT_SYNTHETIC_SCAN_POSES_H_
