#include "scout/explore/collision_guard.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <vector>

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

// Moves 'value' toward 'target' by at most 'max_step'.
double Ramp(double value, double target, double max_step) {
  return value + std::clamp(target - value, -max_step, max_step);
}

// The arcs the guard may steer instead of curvature k at speed v, nearest
// first and turning toward -side first at each step (curvature k +- j steps
// up to steer_max_curvature_per_m; slower where the turn rate would exceed
// max_angular_radps). Returns the first arc for which passes(arc, curvature)
// holds, if any.
template <typename Passes>
std::optional<VelocityCommand> NearestSteeredArc(double v, double k, double side,
                                                 const CollisionGuardOptions& options,
                                                 double max_angular_radps, const Passes& passes) {
  const int steps = static_cast<int>(
      std::floor(options.steer_max_curvature_per_m / options.steer_step_per_m + 1e-9));
  for (int j = 1; j <= steps; ++j) {
    for (const double sign : {-side, side}) {
      const double kc = k + sign * j * options.steer_step_per_m;
      double vc = v;
      if (std::abs(vc * kc) > max_angular_radps) vc = max_angular_radps / std::abs(kc);
      if (vc <= 0.0) continue;
      const VelocityCommand arc{vc, vc * kc};
      if (passes(arc, kc)) return arc;
    }
  }
  return std::nullopt;
}

// How far the robot must turn on the spot toward 'direction' (+1: left), in
// steps of 5 degrees up to half a turn, before driving straight ahead for
// 0.1 m approaches no obstacle within keep_m; +infinity when it never does.
double TurnToClear(double direction, const std::vector<Eigen::Vector2d>& obstacles, double keep_m) {
  constexpr double kReachM = 0.1;
  constexpr double kStepRad = 5.0 * std::numbers::pi / 180.0;
  std::vector<Eigen::Vector2d> near;
  for (const Eigen::Vector2d& p : obstacles) {
    if (p.norm() <= kReachM + keep_m) near.push_back(p);
  }
  std::vector<Eigen::Vector2d> turned(near.size());
  for (int i = 0; i * kStepRad <= std::numbers::pi + 1e-9; ++i) {
    const Eigen::Rotation2Dd to_robot(-direction * i * kStepRad);
    for (size_t j = 0; j < near.size(); ++j) turned[j] = to_robot * near[j];
    if (!std::isfinite(HitDistance(0.0, kReachM, keep_m, turned, nullptr))) return i * kStepRad;
  }
  return std::numeric_limits<double>::infinity();
}

// The command of a robot that stops short of an obstacle on 'side' (+1:
// left): no forward speed, and a turn on the spot, toward the follower's
// turn if that is at least stop_turn_radps, else away from the obstacle;
// but the other way when that clears the way ahead by a turn at least
// kMarginRad shorter. Keeping a decisive turn toward what stops the robot
// deadlocked it: at willow-garage (seed 2, with the visible gain) the robot
// stood 200 s with a return 3 cm from its disc ahead-left while the follower
// turned left toward its path, which put the return squarely ahead (the way
// cleared 20 degrees to the right, 150 to the left, in TurnToClear's steps);
// every goal there failed in turn.
VelocityCommand StopAndTurnAway(const VelocityCommand& command, double side,
                                const std::vector<Eigen::Vector2d>& obstacles, double keep_m,
                                const CollisionGuardOptions& options, double max_angular_radps) {
  const double rate = std::min(options.stop_turn_radps, max_angular_radps);
  if (rate <= 0.0) return {0.0, command.angular_radps};
  const bool decisive = std::abs(command.angular_radps) >= rate;
  const double preferred = decisive ? (command.angular_radps > 0.0 ? 1.0 : -1.0) : -side;
  // A turn shorter by less than this does not overrule the preference (a
  // wall straight ahead clears about as soon either way).
  constexpr double kMarginRad = 30.0 * std::numbers::pi / 180.0;
  const double direction = TurnToClear(-preferred, obstacles, keep_m) + kMarginRad <
                                   TurnToClear(preferred, obstacles, keep_m)
                               ? -preferred
                               : preferred;
  if (decisive && direction == preferred) return {0.0, command.angular_radps};
  return {0.0, direction * rate};
}

// The commanded arc alone, as if speed and turn rate changed at once.
GuardedCommand GuardCommandedArc(const VelocityCommand& command,
                                 const std::vector<Eigen::Vector2d>& obstacles,
                                 double robot_radius_m, const CollisionGuardOptions& options,
                                 double max_angular_radps);

}  // namespace

bool CanStopAfter(const VelocityCommand& command, const BaseMotion& base,
                  const std::vector<Eigen::Vector2d>& obstacles, double robot_radius_m,
                  double clearance_m) {
  if (!(base.max_linear_accel_mps2 > 0.0) || !(base.max_angular_accel_radps2 > 0.0) ||
      !(base.control_period_s > 0.0) || !std::isfinite(base.linear_mps) ||
      !std::isfinite(base.angular_radps) || !std::isfinite(command.linear_mps) ||
      !std::isfinite(command.angular_radps)) {
    throw std::invalid_argument(
        "CanStopAfter: expected positive accelerations and control period, finite velocities");
  }
  const double keep_m = robot_radius_m + clearance_m;
  const double a = base.max_linear_accel_mps2;
  const double period_s = base.control_period_s;
  // How far the disc's centre can get: the fastest speed reachable within the
  // period, held for the period, then braked.
  const double peak_mps =
      std::max(std::abs(base.linear_mps), std::abs(command.linear_mps)) + a * period_s;
  const double reach_m = peak_mps * period_s + peak_mps * peak_mps / (2.0 * a) + kStepM;
  std::vector<Eigen::Vector2d> near;
  std::vector<double> start_m;
  for (const Eigen::Vector2d& p : obstacles) {
    const double d = p.norm();
    if (std::isfinite(d) && d < reach_m + keep_m) {
      near.push_back(p);
      start_m.push_back(d);
    }
  }
  if (near.empty()) return true;
  // Steps short enough that the disc moves at most ~5 mm between checks.
  const double dt_s = std::min(period_s / 5.0, 0.01);
  double v = base.linear_mps;
  double w = base.angular_radps;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  double heading_rad = 0.0;
  const auto advance_and_check = [&](double v_target, double w_target) {
    v = Ramp(v, v_target, a * dt_s);
    w = Ramp(w, w_target, base.max_angular_accel_radps2 * dt_s);
    const double mid_rad = heading_rad + 0.5 * w * dt_s;
    position += v * dt_s * Eigen::Vector2d(std::cos(mid_rad), std::sin(mid_rad));
    heading_rad += w * dt_s;
    for (size_t i = 0; i < near.size(); ++i) {
      const double d = (near[i] - position).norm();
      if (d < keep_m && d < start_m[i]) return false;
    }
    return true;
  };
  for (double t_s = 0.0; t_s < period_s - 1e-12; t_s += dt_s) {
    if (!advance_and_check(command.linear_mps, command.angular_radps)) return false;
  }
  // Braking ends when the wheels stop translating; turning on the spot
  // afterwards sweeps nothing.
  while (v != 0.0) {
    if (!advance_and_check(0.0, 0.0)) return false;
  }
  return true;
}

void Validate(const CollisionGuardOptions& o) {
  CheckAtLeast("guard", "clearance_m", o.clearance_m, 0.0);
  CheckAtLeast("guard", "horizon_s", o.horizon_s, 0.0);
  CheckAtLeast("guard", "steer_max_curvature_per_m", o.steer_max_curvature_per_m, 0.0);
  CheckAtLeast("guard", "steer_step_per_m", o.steer_step_per_m, 0.0, /*strict=*/true);
  CheckAtLeast("guard", "memory_s", o.memory_s, 0.0);
  CheckAtLeast("guard", "stop_turn_radps", o.stop_turn_radps, 0.0);
}

GuardedCommand GuardCommand(const VelocityCommand& command,
                            const std::vector<Eigen::Vector2d>& obstacles, double robot_radius_m,
                            const CollisionGuardOptions& options, double max_angular_radps,
                            const BaseMotion* base) {
  GuardedCommand out =
      GuardCommandedArc(command, obstacles, robot_radius_m, options, max_angular_radps);
  if (!options.predict_motion || base == nullptr || options.horizon_s <= 0.0 ||
      command.linear_mps < 0.0) {
    return out;
  }
  if (CanStopAfter(out.command, *base, obstacles, robot_radius_m, options.clearance_m)) {
    return out;
  }
  // The nearest arc at the commanded speed after which the robot can still
  // stop, turning away from the nearest obstacle ahead first.
  const double v = command.linear_mps;
  if (v > 0.0) {
    const double k = command.angular_radps / v;
    double side = 1.0;
    HitDistance(k, v * options.horizon_s + 0.5, robot_radius_m + options.clearance_m, obstacles,
                &side);
    const std::optional<VelocityCommand> arc = NearestSteeredArc(
        v, k, side, options, max_angular_radps, [&](const VelocityCommand& c, double) {
          return CanStopAfter(c, *base, obstacles, robot_radius_m, options.clearance_m);
        });
    if (arc) return {*arc, arc->linear_mps < v, false, true};
    return {StopAndTurnAway(command, side, obstacles, robot_radius_m + options.clearance_m, options,
                            max_angular_radps),
            true, true, false};
  }
  return {{0.0, 0.0}, true, true, false};
}

namespace {

GuardedCommand GuardCommandedArc(const VelocityCommand& command,
                                 const std::vector<Eigen::Vector2d>& obstacles,
                                 double robot_radius_m, const CollisionGuardOptions& options,
                                 double max_angular_radps) {
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
  const std::optional<VelocityCommand> arc = NearestSteeredArc(
      v, k, side, options, max_angular_radps, [&](const VelocityCommand& c, double kc) {
        return !std::isfinite(
            HitDistance(kc, c.linear_mps * options.horizon_s, keep_m, obstacles, nullptr));
      });
  if (arc) {
    out.command = *arc;
    out.steered = true;
    return out;
  }
  const double free_m = hit_m - kStepM;
  const double v_safe = free_m / options.horizon_s;
  if (free_m < kStepM) {
    // Turn on the spot (the disc sweeps nothing): see StopAndTurnAway.
    out.command = StopAndTurnAway(command, side, obstacles, keep_m, options, max_angular_radps);
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

}  // namespace

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
  no_steering.stop_turn_radps = 0.0;  // backing up stops straight
  GuardedCommand out = GuardCommand({-command.linear_mps, -command.angular_radps}, mirrored,
                                    robot_radius_m, no_steering);
  out.command = {-out.command.linear_mps, -out.command.angular_radps};
  return out;
}

}  // namespace scout::explore
