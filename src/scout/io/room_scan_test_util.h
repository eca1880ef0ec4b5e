#ifndef SCOUT_IO_ROOM_SCAN_TEST_UTIL_H_
#define SCOUT_IO_ROOM_SCAN_TEST_UTIL_H_

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "scout/geometry/rigid_transform.h"

namespace scout::io::testing {

// Returns of a lidar at 'pose' on the walls of a 10 m x 6 m room (and a
// pillar), 1 degree apart, exact: the walls are where the poses say.
inline std::vector<Eigen::Vector2d> RoomScan(const geometry::Rigid2d& pose) {
  std::vector<Eigen::Vector2d> returns;
  for (int k = 0; k < 360; ++k) {
    const double angle = pose.theta() + k * M_PI / 180.0;
    const Eigen::Vector2d d(std::cos(angle), std::sin(angle));
    double best = 1e9;
    // Walls x = +-5, y = +-3; the pillar's face x = 1 for |y| < 0.5.
    for (const double wall : {-5.0, 5.0, 1.0}) {
      if (std::abs(d.x()) < 1e-9) continue;
      const double t = (wall - pose.x()) / d.x();
      const double y = pose.y() + t * d.y();
      if (t > 0 && (wall != 1.0 || std::abs(y) < 0.5)) best = std::min(best, t);
    }
    for (const double wall : {-3.0, 3.0}) {
      if (std::abs(d.y()) < 1e-9) continue;
      const double t = (wall - pose.y()) / d.y();
      if (t > 0) best = std::min(best, t);
    }
    returns.push_back(pose.inverse() * (pose.translation() + best * d));
  }
  return returns;
}

}  // namespace scout::io::testing

#endif  // SCOUT_IO_ROOM_SCAN_TEST_UTIL_H_
