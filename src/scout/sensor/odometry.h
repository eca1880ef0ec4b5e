#ifndef SCOUT_SENSOR_ODOMETRY_H_
#define SCOUT_SENSOR_ODOMETRY_H_

#include "scout/geometry/rigid_transform.h"

namespace scout::sensor {

// One wheel-odometry reading (nav_msgs/Odometry, CARMEN ODOM): the robot base
// pose in the odometry frame at 'time_s'. Only differences between readings
// carry information; the odometry frame itself drifts.
struct Odometry {
  double time_s = 0.0;
  geometry::Rigid2d pose;
};

}  // namespace scout::sensor

#endif  // SCOUT_SENSOR_ODOMETRY_H_
