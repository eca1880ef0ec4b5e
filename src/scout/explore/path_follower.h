#ifndef SCOUT_EXPLORE_PATH_FOLLOWER_H_
#define SCOUT_EXPLORE_PATH_FOLLOWER_H_

#include <Eigen/Core>
#include <vector>

#include "scout/geometry/rigid_transform.h"

namespace scout::explore {

// Pure pursuit for a differential-drive robot.
struct PathFollowerOptions {
  // Distance along the path to the point the robot steers towards, metres.
  // Shorter tracks corners tighter; longer drives smoother.
  double lookahead_m = 0.5;
  double max_linear_speed_mps = 0.5;
  double max_angular_speed_radps = 1.0;
  // With the target more than this far off the heading, turn on the spot
  // (a disc robot can; driving a wide arc could touch a wall).
  double rotate_in_place_heading_rad = 0.785;
  // Turning on the spot: angular speed = gain · heading error (clamped).
  double rotate_gain_per_s = 2.0;
  // The goal counts as reached within this distance, metres.
  double goal_tolerance_m = 0.25;
  // Closer to the goal than this, the linear speed falls in proportion ...
  double slow_down_distance_m = 0.6;
  // ... but not below this.
  double min_linear_speed_mps = 0.05;
};

// Throws std::invalid_argument naming the key of a bad value.
void Validate(const PathFollowerOptions& options);

struct VelocityCommand {
  double linear_mps = 0.0;
  double angular_radps = 0.0;
};

struct FollowStatus {
  VelocityCommand command;  // zero when reached or without a path
  bool reached = false;
  // Path length still ahead of the robot (plus its distance to the path), m.
  double remaining_m = 0.0;
};

class PathFollower {
 public:
  // Throws std::invalid_argument on bad options.
  explicit PathFollower(const PathFollowerOptions& options);

  // Replaces the path (world points, at least one) and restarts from its beginning.
  void SetPath(std::vector<Eigen::Vector2d> path);
  void Clear() { path_.clear(); }
  bool has_path() const { return !path_.empty(); }
  const std::vector<Eigen::Vector2d>& path() const { return path_; }

  // Returns the command for the robot at 'pose' (global frame). Progress along
  // the path only moves forward, so a path that doubles back is followed, not
  // cut short.
  FollowStatus Update(const geometry::Rigid2d& pose);

  const PathFollowerOptions& options() const { return options_; }

 private:
  // Returns the point at arc length 's' along the path.
  Eigen::Vector2d PointAt(double s) const;
  // Moves progress_m_ forward to the projection of 'p'; returns its distance.
  double AdvanceProgress(const Eigen::Vector2d& p);

  PathFollowerOptions options_;
  std::vector<Eigen::Vector2d> path_;
  std::vector<double> arc_;  // arc length at each vertex
  double progress_m_ = 0.0;
};

}  // namespace scout::explore

#endif  // SCOUT_EXPLORE_PATH_FOLLOWER_H_
