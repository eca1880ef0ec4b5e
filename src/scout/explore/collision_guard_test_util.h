#ifndef SCOUT_EXPLORE_COLLISION_GUARD_TEST_UTIL_H_
#define SCOUT_EXPLORE_COLLISION_GUARD_TEST_UTIL_H_

// RapidCheck generators shared by the collision guard's tests (call them
// inside a property only).
#include <rapidcheck.h>

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "scout/explore/path_follower.h"

namespace scout::explore::testing {

// 1-19 point obstacles ahead of the robot (within ±90°), 0.25-2.25 m away:
// outside the disc plus clearance.
inline std::vector<Eigen::Vector2d> RandomObstaclesAhead() {
  const int n = *rc::gen::inRange(1, 20);
  std::vector<Eigen::Vector2d> obstacles;
  for (int i = 0; i < n; ++i) {
    const double angle = *rc::gen::inRange(-157, 158) * 0.01;
    const double range = 0.25 + *rc::gen::inRange(0, 200) * 0.01;
    obstacles.push_back(range * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
  }
  return obstacles;
}

// A forward command: 0.01-0.5 m/s, -1 to 1 rad/s.
inline VelocityCommand RandomForwardCommand() {
  return {*rc::gen::inRange(1, 51) * 0.01, *rc::gen::inRange(-100, 101) * 0.01};
}

}  // namespace scout::explore::testing

#endif  // SCOUT_EXPLORE_COLLISION_GUARD_TEST_UTIL_H_
