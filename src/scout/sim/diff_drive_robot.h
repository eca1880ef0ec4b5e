#ifndef SCOUT_SIM_DIFF_DRIVE_ROBOT_H_
#define SCOUT_SIM_DIFF_DRIVE_ROBOT_H_

#include "scout/geometry/rigid_transform.h"
#include "scout/grid/occupancy_map.h"
#include "scout/sim/disc_collision_checker.h"

namespace scout::sim {

// A differential-drive base shaped as a disc. Defaults are a typical indoor
// base (TurtleBot 2 / Pioneer class): 0.20 m radius as in ALGORITHMS §8, top
// speeds 0.5 m/s and 1 rad/s, and accelerations (0.5 m/s^2, 2 rad/s^2) that
// bring it from full speed to rest in 1 s and 0.5 s. Braking obeys the same
// limits as speeding up.
struct DiffDriveOptions {
  double radius_m = 0.20;
  double max_linear_speed_mps = 0.5;
  double max_angular_speed_radps = 1.0;
  double max_linear_accel_mps2 = 0.5;
  double max_angular_accel_radps2 = 2.0;
  // Longest swept distance between two collision checks, in cells of the
  // world map: a quarter cell cannot skip over an obstacle cell and overlaps
  // an obstacle by at most that much before a check sees it.
  double collision_substep_cells = 0.25;
};

// Throws InputError naming the key ("robot.<key>") if an option is invalid.
void CheckDiffDriveOptions(const DiffDriveOptions& options);

// Returns 'pose' after moving for 't_s' seconds at constant body velocities
// (v, omega): exactly along the circular arc (a straight line for omega = 0).
geometry::Rigid2d IntegrateArc(const geometry::Rigid2d& pose, double v_mps, double omega_radps,
                               double t_s);

// What happened during one Step.
struct DiffDriveStepResult {
  // The swept disc hit an obstacle; the robot stopped short of it.
  bool blocked = false;
  // True distance the robot's centre travelled during the step.
  double distance_m = 0.0;
};

// The robot's TRUE state (pose, body velocities) in a TRUE world map.
class DiffDriveRobot {
 public:
  // Throws InputError if an option is invalid or the disc at 'start' overlaps
  // an obstacle. The map is read only here (its clearance is precomputed).
  DiffDriveRobot(const grid::OccupancyMap& world_map, const DiffDriveOptions& options,
                 const geometry::Rigid2d& start);

  // Advances by 'dt_s' seconds towards the commanded body velocities: each
  // velocity first moves towards its command by at most accel * dt and is
  // clamped to the top speed, then is held for the whole step (exact arc).
  // The swept disc is checked in substeps; on a hit the robot stays at the
  // last collision-free substep with v = omega = 0. Throws
  // std::invalid_argument unless dt_s > 0 and the commands are finite.
  DiffDriveStepResult Step(double v_cmd_mps, double omega_cmd_radps, double dt_s);

  // Returns the true pose (world frame).
  const geometry::Rigid2d& pose() const { return pose_; }
  double linear_velocity_mps() const { return v_mps_; }
  double angular_velocity_radps() const { return omega_radps_; }
  // Returns the number of collisions (contacts): a contact begins with a
  // blocked step and lasts until the robot is a substep clear of every
  // obstacle, so pushing against or sliding along a wall is one collision.
  int collisions() const { return collisions_; }
  // Returns the number of steps whose motion was blocked.
  int blocked_steps() const { return blocked_steps_; }
  // Returns the true distance travelled by the centre (arc length).
  double path_length_m() const { return path_length_m_; }
  const DiffDriveOptions& options() const { return options_; }
  const DiscCollisionChecker& collision_checker() const { return checker_; }

 private:
  DiffDriveOptions options_;
  DiscCollisionChecker checker_;
  double max_substep_m_;
  geometry::Rigid2d pose_;
  double v_mps_ = 0.0;
  double omega_radps_ = 0.0;
  int collisions_ = 0;
  int blocked_steps_ = 0;
  bool in_contact_ = false;
  double path_length_m_ = 0.0;
};

}  // namespace scout::sim

#endif  // SCOUT_SIM_DIFF_DRIVE_ROBOT_H_
