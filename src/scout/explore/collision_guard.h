#ifndef SCOUT_EXPLORE_COLLISION_GUARD_H_
#define SCOUT_EXPLORE_COLLISION_GUARD_H_

#include <Eigen/Core>
#include <vector>

#include "scout/explore/path_follower.h"

namespace scout::explore {

// A last check of each forward command against what the lidar sees now.
//
// The path follower trusts the SLAM map, which can place a door post a few
// centimetres off; pure pursuit cuts corners besides. In the office (seed 1)
// the robot clipped one door post eight times in a row: each time it got
// stuck, backed up, failed the goal, and retried it from the same side. The
// guard rolls the commanded arc forward over horizon_s and slows the robot so
// that it stops before its disc comes within clearance_m of a scan return it
// is approaching. Turning on the spot is never restricted (the disc sweeps
// nothing), so the follower can still turn toward a clear heading.
struct CollisionGuardOptions {
  double clearance_m = 0.03;
  // 0 disables the guard.
  double horizon_s = 1.0;
};

// Throws std::invalid_argument naming the key of a bad value.
void Validate(const CollisionGuardOptions& options);

struct GuardedCommand {
  VelocityCommand command;
  // The forward speed was cut (to zero when 'stopped').
  bool limited = false;
  bool stopped = false;
};

// Returns 'command' with its forward speed limited so that the robot (a disc
// of 'robot_radius_m' at the origin facing +x) does not come within
// clearance_m of any of 'obstacles' (robot frame, metres) that it approaches
// along the commanded arc within horizon_s. Backward and turning-only
// commands pass unchanged.
GuardedCommand GuardCommand(const VelocityCommand& command,
                            const std::vector<Eigen::Vector2d>& obstacles, double robot_radius_m,
                            const CollisionGuardOptions& options);

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_COLLISION_GUARD_H_
