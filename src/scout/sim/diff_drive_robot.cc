#include "scout/sim/diff_drive_robot.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "scout/common/error.h"

namespace scout::sim {
namespace {

void RequireRobotOption(bool ok, const std::string& key, double value,
                        const std::string& expected) {
  if (!ok) {
    std::ostringstream message;
    message << "robot." << key << " = " << value << ": expected " << expected;
    throw InputError(message.str());
  }
}

// Returns sin(x) / x, accurate near 0 where the quotient loses digits.
double Sinc(double x) {
  if (std::abs(x) < 1e-4) return 1.0 - x * x / 6.0;
  return std::sin(x) / x;
}

// Returns 'current' moved towards 'command' by at most 'max_change', then
// clamped to [-max_abs, max_abs].
double Ramp(double current, double command, double max_change, double max_abs) {
  const double next = current + std::clamp(command - current, -max_change, max_change);
  return std::clamp(next, -max_abs, max_abs);
}

}  // namespace

void CheckDiffDriveOptions(const DiffDriveOptions& o) {
  // Written as !(x > 0) so NaN fails too.
  RequireRobotOption(o.radius_m > 0.0, "radius_m", o.radius_m, "> 0");
  RequireRobotOption(o.max_linear_speed_mps > 0.0, "max_linear_speed_mps", o.max_linear_speed_mps,
                     "> 0");
  RequireRobotOption(o.max_angular_speed_radps > 0.0, "max_angular_speed_radps",
                     o.max_angular_speed_radps, "> 0");
  RequireRobotOption(o.max_linear_accel_mps2 > 0.0, "max_linear_accel_mps2",
                     o.max_linear_accel_mps2, "> 0");
  RequireRobotOption(o.max_angular_accel_radps2 > 0.0, "max_angular_accel_radps2",
                     o.max_angular_accel_radps2, "> 0");
  // Finer than a hundredth of a cell only costs time (1e-9 never finished a step).
  RequireRobotOption(o.collision_substep_cells >= 0.01 && o.collision_substep_cells <= 1.0,
                     "collision_substep_cells", o.collision_substep_cells, "in [0.01, 1]");
}

geometry::Rigid2d IntegrateArc(const geometry::Rigid2d& pose, double v_mps, double omega_radps,
                               double t_s) {
  // The chord of an arc turning by a = omega t has length v t sinc(a / 2) and
  // points along the mean heading, which also covers omega = 0 exactly.
  const double turn_rad = omega_radps * t_s;
  const double chord_m = v_mps * t_s * Sinc(0.5 * turn_rad);
  const double chord_heading_rad = pose.theta() + 0.5 * turn_rad;
  const Eigen::Vector2d end =
      pose.translation() +
      chord_m * Eigen::Vector2d(std::cos(chord_heading_rad), std::sin(chord_heading_rad));
  return geometry::Rigid2d(end, pose.theta() + turn_rad);
}

DiffDriveRobot::DiffDriveRobot(const grid::OccupancyMap& world_map, const DiffDriveOptions& options,
                               const geometry::Rigid2d& start)
    : options_((CheckDiffDriveOptions(options), options)),
      checker_(world_map, options.radius_m),
      max_substep_m_(options.collision_substep_cells * world_map.limits.resolution()),
      pose_(start) {
  if (checker_.Collides(start.translation())) {
    std::ostringstream message;
    message << "robot start " << start << ": the disc of radius " << options.radius_m
            << " m overlaps an occupied or unknown cell";
    throw InputError(message.str());
  }
}

DiffDriveStepResult DiffDriveRobot::Step(double v_cmd_mps, double omega_cmd_radps, double dt_s) {
  if (!(dt_s > 0.0) || !std::isfinite(dt_s) || !std::isfinite(v_cmd_mps) ||
      !std::isfinite(omega_cmd_radps)) {
    throw std::invalid_argument("DiffDriveRobot::Step: expected dt_s > 0 and finite commands");
  }
  v_mps_ =
      Ramp(v_mps_, v_cmd_mps, options_.max_linear_accel_mps2 * dt_s, options_.max_linear_speed_mps);
  omega_radps_ = Ramp(omega_radps_, omega_cmd_radps, options_.max_angular_accel_radps2 * dt_s,
                      options_.max_angular_speed_radps);

  // A disc turning in place sweeps nothing new, so only the arc length sets
  // the number of checks. Each substep pose is integrated from the start pose
  // so the final pose carries no substep round-off.
  const double arc_m = std::abs(v_mps_) * dt_s;
  const int substeps = std::max(1, static_cast<int>(std::ceil(arc_m / max_substep_m_)));
  const geometry::Rigid2d start = pose_;
  DiffDriveStepResult result;
  for (int k = 1; k <= substeps; ++k) {
    const double t_s = dt_s * k / substeps;
    const geometry::Rigid2d next = IntegrateArc(start, v_mps_, omega_radps_, t_s);
    if (arc_m > 0.0 && checker_.Collides(next.translation())) {
      result.blocked = true;
      break;
    }
    pose_ = next;
    result.distance_m = arc_m * k / substeps;
  }
  path_length_m_ += result.distance_m;

  if (result.blocked) {
    v_mps_ = 0.0;
    omega_radps_ = 0.0;
    ++blocked_steps_;
    if (!in_contact_) ++collisions_;
    in_contact_ = true;
  } else if (in_contact_ &&
             !checker_.Collides(pose_.translation(), options_.radius_m + max_substep_m_)) {
    // A contact ends once the robot is a whole substep clear of everything,
    // so creeping back into the same wall is not another collision.
    in_contact_ = false;
  }
  return result;
}

}  // namespace scout::sim
