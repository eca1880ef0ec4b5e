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

}  // namespace

void Validate(const CollisionGuardOptions& o) {
  CheckAtLeast("guard", "clearance_m", o.clearance_m, 0.0);
  CheckAtLeast("guard", "horizon_s", o.horizon_s, 0.0);
}

GuardedCommand GuardCommand(const VelocityCommand& command,
                            const std::vector<Eigen::Vector2d>& obstacles, double robot_radius_m,
                            const CollisionGuardOptions& options) {
  GuardedCommand out{command, false, false};
  const double v = command.linear_mps;
  if (v <= 0.0 || options.horizon_s <= 0.0) return out;
  const double k = command.angular_radps / v;
  const double reach_m = v * options.horizon_s;
  const double keep_m = robot_radius_m + options.clearance_m;
  constexpr double kStepM = 0.01;
  // Arc length at which the disc first comes within keep_m of a point it is
  // approaching (closer than it stands now).
  double hit_m = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& p : obstacles) {
    const double d0 = p.norm();
    if (!std::isfinite(d0) || d0 > reach_m + keep_m) continue;
    for (double s = kStepM; s <= std::min(reach_m, hit_m) + 1e-12; s += kStepM) {
      const double d = (p - OnArc(k, s)).norm();
      if (d < keep_m && d < d0) {
        hit_m = s;
        break;
      }
    }
  }
  if (!std::isfinite(hit_m)) return out;
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

}  // namespace scout::explore
