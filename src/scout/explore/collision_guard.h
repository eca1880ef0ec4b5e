#ifndef SCOUT_EXPLORE_COLLISION_GUARD_H_
#define SCOUT_EXPLORE_COLLISION_GUARD_H_

#include <Eigen/Core>
#include <limits>
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
  // When the commanded arc would be slowed, the guard first looks for the
  // nearest arc whose curvature differs by at most this much (1/m, in steps
  // of steer_step_per_m) that is clear over the whole horizon, and drives
  // that instead; the follower steers back to its path next cycle. Where
  // the path runs closer to a wall than the map says, the robot otherwise
  // stops, turns on the spot toward its path, and stops again: in office
  // seed 2 it got stuck 16 times in 150 s at two places beside walls (at
  // the second, the scan's nearest return 0.23-0.25 m to its side), a goal
  // failing each time. 0: never steer (only slow down).
  double steer_max_curvature_per_m = 2.0;
  double steer_step_per_m = 0.25;
  // The lidar sees only ahead, so backing up is checked against the returns
  // of the scans of the last memory_s seconds as well (placed by local SLAM,
  // which holds over seconds where the global map may be 0.1 m off). In
  // the office (seed 4, narrow_margin_m 0.05) the robot turned round in a
  // 0.6 m gap beside a desk and backed into the wall it had seen 5 s
  // before, which its map placed 0.1 m too far. 0: blind backing up (only
  // the map's check, GoalManagerOptions::back_up_look_behind_m).
  double memory_s = 10.0;
};

// Throws std::invalid_argument naming the key of a bad value.
void Validate(const CollisionGuardOptions& options);

struct GuardedCommand {
  VelocityCommand command;
  // The forward speed was cut (to zero when 'stopped').
  bool limited = false;
  bool stopped = false;
  // Another arc than the commanded one was chosen (clear over the horizon).
  bool steered = false;
};

// Returns 'command' with its forward speed limited so that the robot (a disc
// of 'robot_radius_m' at the origin facing +x) does not come within
// clearance_m of any of 'obstacles' (robot frame, metres) that it approaches
// along the commanded arc within horizon_s, unless a nearby clear arc is
// steered instead (see steer_max_curvature_per_m; its turn rate at most
// max_angular_radps, slowing down for it if need be). Backward and
// turning-only commands pass unchanged.
GuardedCommand GuardCommand(const VelocityCommand& command,
                            const std::vector<Eigen::Vector2d>& obstacles, double robot_radius_m,
                            const CollisionGuardOptions& options,
                            double max_angular_radps = std::numeric_limits<double>::infinity());

// The same check for a backward command (linear_mps < 0): the robot stops
// (never steers) before its disc comes within clearance_m of any of
// 'obstacles' (robot frame, metres; behind the robot: x < 0) that it
// approaches backing along the commanded arc within horizon_s. Forward and
// turning-only commands pass unchanged.
GuardedCommand GuardBackward(const VelocityCommand& command,
                             const std::vector<Eigen::Vector2d>& obstacles, double robot_radius_m,
                             const CollisionGuardOptions& options);

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_COLLISION_GUARD_H_
