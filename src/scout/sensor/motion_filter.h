#ifndef SCOUT_SENSOR_MOTION_FILTER_H_
#define SCOUT_SENSOR_MOTION_FILTER_H_

#include <cstdint>
#include <numbers>
#include <optional>

#include "scout/geometry/rigid_transform.h"

namespace scout::sensor {

// Defaults: ALGORITHMS §7 (Cartographer's 2D motion filter).
struct MotionFilterOptions {
  // A pose this long after the last accepted one is accepted even without motion.
  double max_time_s = 5.0;
  // A pose this far from the last accepted one is accepted.
  double max_distance_m = 0.2;
  // A pose turned this much from the last accepted one is accepted.
  double max_angle_rad = 1.0 * std::numbers::pi / 180.0;
};

// Throws std::invalid_argument naming the first invalid option.
void Validate(const MotionFilterOptions& options);

// Drops scans taken while the robot barely moved, so submaps are not flooded
// with near-duplicate scans of a standing robot.
class MotionFilter {
 public:
  // Throws std::invalid_argument on invalid options.
  explicit MotionFilter(const MotionFilterOptions& options);

  // Returns true (and remembers 'pose' as the last accepted) if this is the
  // first pose, or if it is at least max_time_s later, max_distance_m away or
  // max_angle_rad turned compared with the last accepted pose.
  bool Accept(double time_s, const geometry::Rigid2d& pose);

  int64_t num_accepted() const { return num_accepted_; }
  int64_t num_total() const { return num_total_; }

 private:
  MotionFilterOptions options_;
  std::optional<double> last_time_s_;
  geometry::Rigid2d last_pose_;
  int64_t num_accepted_ = 0;
  int64_t num_total_ = 0;
};

}  // namespace scout::sensor

#endif  // SCOUT_SENSOR_MOTION_FILTER_H_
