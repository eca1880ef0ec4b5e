#ifndef SCOUT_IO_TRAJECTORY_H_
#define SCOUT_IO_TRAJECTORY_H_

#include "scout/geometry/rigid_transform.h"

namespace scout::io {

// A robot pose (base frame -> map frame) at a time, in seconds of the
// recording's own time base.
struct StampedPose {
  double time_s = 0.0;
  geometry::Rigid2d pose;
};

}  // namespace scout::io

#endif  // SCOUT_IO_TRAJECTORY_H_
