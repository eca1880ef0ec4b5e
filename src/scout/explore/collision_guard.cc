#include "scout/explore/collision_guard.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scout/explore/option_check.h"

namespace scout::explore {
namespace {

// Position after driving arc length s along an arc of curvature k from the
// origin, heading +x.
Eigen::Vector2d OnArc(double k, double s) {
  if (std::abs(k * s) < 1e-9) return {s, 0.0};
  return {std::sin(k * s) / k, (1.0 - std::cos(k * s)) / k};
}

// Arc length along the arc of curvature k at which the disc first comes
// within keep_m of an obstacle it is approaching (closer than it stands now),
// searched up to reach_m; +infinity when none. 'side' gets the sign of the
// lateral offset of that obstacle (+1: left).
constexpr double kStepM = 0.01;
double HitDistance(double k, double reach_m, double keep_m,
                   const std::vector<Eigen::Vector2d>& obstacles, double* side) {
  double hit_m = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& p : obstacles) {
    const double d0 = p.norm();
    if (!std::isfinite(d0) || d0 > reach_m + keep_m) continue;
    for (double s = kStepM; s <= std::min(reach_m, hit_m) + 1e-12; s += kStepM) {
      const double d = (p - OnArc(k, s)).norm();
      if (d < keep_m && d < d0) {
        hit_m = s;
        if (side) *side = p.y() >= 0.0 ? 1.0 : -1.0;
        break;
      }
    }
  }
  return hit_m;
}

}  // namespace

void Validate(const CollisionGuardOptions& o) {
  CheckAtLeast("guard", "clearance_m", o.clearance_m, 0.0);
  CheckAtLeast("guard", "horizon_s", o.horizon_s, 0.0);
  CheckAtLeast("guard", "steer_max_curvature_per_m", o.steer_max_curvature_per_m, 0.0);
  CheckAtLeast("guard", "steer_step_per_m", o.steer_step_per_m, 0.0, /*strict=*/true);
  CheckAtLeast("guard", "memory_s", o.memory_s, 0.0);
}

GuardedCommand GuardCommand(const VelocityCommand& command,
                            const std::vector<Eigen::Vector2d>& obstacles, double robot_radius_m,
                            const CollisionGuardOptions& options, double max_angular_radps) {
  GuardedCommand out{command, false, false, false};
  const double v = command.linear_mps;
  if (v <= 0.0 || options.horizon_s <= 0.0) return out;
  const double k = command.angular_radps / v;
  const double reach_m = v * options.horizon_s;
  const double keep_m = robot_radius_m + options.clearance_m;
  double side = 0.0;
  const double hit_m = HitDistance(k, reach_m, keep_m, obstacles, &side);
  if (!std::isfinite(hit_m)) return out;
  // The nearest clear arc, turning away from the obstacle first.
  const int steps = static_cast<int>(
      std::floor(options.steer_max_curvature_per_m / options.steer_step_per_m + 1e-9));
  for (int j = 1; j <= steps; ++j) {
    for (const double sign : {-side, side}) {
      const double kc = k + sign * j * options.steer_step_per_m;
      double vc = v;
      if (std::abs(vc * kc) > max_angular_radps) vc = max_angular_radps / std::abs(kc);
      if (vc <= 0.0) continue;
      if (std::isfinite(HitDistance(kc, vc * options.horizon_s, keep_m, obstacles, nullptr))) {
        continue;
      }
      out.command = {vc, vc * kc};
      out.steered = true;
      return out;
    }
  }
  const double free_m = hit_m - kStepM;
  const double v_safe = free_m / options.horizon_s;
  if (free_m < kStepM) {
    // Turn on the spot toward the follower's heading; the disc sweeps nothing.
    out.command.linear_mps = 0.0;
    out.limited = out.stopped = true;
    return out;
  }
  if (v_safe < v) {
    out.command.linear_mps = v_safe;
    out.command.angular_radps = command.angular_radps * v_safe / v;  // the same arc
    out.limited = true;
  }
  return out;
}

GuardedCommand GuardBackward(const VelocityCommand& command,
                             const std::vector<Eigen::Vector2d>& obstacles, double robot_radius_m,
                             const CollisionGuardOptions& options) {
  if (command.linear_mps >= 0.0) return {command, false, false, false};
  // Mirrored across the robot's y axis, backing along (v, w) is driving
  // forward along (-v, -w): the forward check applies unchanged.
  std::vector<Eigen::Vector2d> mirrored;
  mirrored.reserve(obstacles.size());
  for (const Eigen::Vector2d& p : obstacles) mirrored.emplace_back(-p.x(), p.y());
  CollisionGuardOptions no_steering = options;
  no_steering.steer_max_curvature_per_m = 0.0;
  GuardedCommand out = GuardCommand({-command.linear_mps, -command.angular_radps}, mirrored,
                                    robot_radius_m, no_steering);
  out.command = {-out.command.linear_mps, -out.command.angular_radps};
  return out;
}

}  // namespace scout::explore
