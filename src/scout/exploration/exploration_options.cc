#include "scout/exploration/exploration_options.h"

#include <algorithm>
#include <boost/geometry.hpp>
#include <cmath>
#include <stdexcept>

#include "scout/common/error.h"
#include "scout/common/format.h"
#include "scout/frontier/update_strategy.h"

namespace scout::exploration {
namespace {

void RequirePositive(double value, const std::string& key) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError("explore." + key + ": expected a positive finite value, got " +
                     FormatNumber(value));
  }
}

bool IsOneOf(const std::string& name, const std::vector<std::string>& names) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string JoinNames(const std::vector<std::string>& names) {
  std::string joined;
  for (const std::string& n : names) joined += (joined.empty() ? "" : ", ") + n;
  return joined;
}

}  // namespace

frontier::FrontierOptions EffectiveFrontierOptions(const ExplorationOptions& options) {
  frontier::FrontierOptions f = options.frontier;
  f.inflation_radius_m = options.explore.frontier_inflation_radius_m;
  return f;
}

explore::TraversabilityOptions PlanningTraversability(const ExplorationOptions& options) {
  explore::TraversabilityOptions t = options.explore.traversability;
  t.robot_radius_m = options.robot.robot.radius_m;
  return t;
}

void CheckExplorationBoundary(const std::vector<Eigen::Vector2d>& boundary) {
  if (!boundary.empty() && boundary.size() < 3) {
    throw InputError("'explore.boundary': expected at least three [x, y] vertices, got " +
                     std::to_string(boundary.size()));
  }
  for (const Eigen::Vector2d& v : boundary) {
    if (!v.allFinite()) throw InputError("'explore.boundary': expected finite coordinates");
  }
  if (boundary.empty()) return;
  // Only a simple polygon has one inside: a bowtie's second lobe would count
  // as outside, and a polygon without area holds nothing.
  namespace bg = boost::geometry;
  using Point = bg::model::d2::point_xy<double>;
  bg::model::ring<Point, /*clockwise=*/false, /*closed=*/false> ring;
  for (const Eigen::Vector2d& v : boundary) ring.push_back(Point(v.x(), v.y()));
  if (bg::intersects(ring)) {
    throw InputError(
        "'explore.boundary': the polygon crosses itself; expected a simple polygon "
        "(edges meeting only at consecutive vertices)");
  }
  if (!(std::abs(bg::area(ring)) > 1e-9)) {
    throw InputError(
        "'explore.boundary': the polygon has no area (its vertices lie on a line); "
        "expected a simple polygon around the start");
  }
}

void CheckExplorationOptions(const ExplorationOptions& options) {
  const ExploreOptions& e = options.explore;
  RequirePositive(e.dt_s, "dt_s");
  RequirePositive(e.max_sim_time_s, "max_sim_time_s");
  RequirePositive(e.no_progress_timeout_s, "no_progress_timeout_s");
  RequirePositive(e.map_update_interval_s, "map_update_interval_s");
  RequirePositive(e.coverage_interval_s, "coverage_interval_s");
  if (!(e.initial_turn_rad >= 0.0) || !std::isfinite(e.initial_turn_rad)) {
    throw InputError("explore.initial_turn_deg: expected a finite value >= 0");
  }
  if (!(e.min_map_gain_m2 >= 0.0) || !std::isfinite(e.min_map_gain_m2)) {
    throw InputError("explore.min_map_gain_m2: expected a finite value >= 0");
  }
  if (!(e.complete_max_reachable_frontier_m >= 0.0) ||
      !std::isfinite(e.complete_max_reachable_frontier_m)) {
    throw InputError("explore.complete_max_reachable_frontier_m: expected a finite value >= 0");
  }
  CheckExplorationBoundary(e.boundary);
  if (!IsOneOf(e.strategy, frontier::StrategyNames())) {
    throw InputError("unknown frontier strategy '" + e.strategy + "': expected one of " +
                     JoinNames(frontier::StrategyNames()));
  }
  if (!IsOneOf(e.goal_policy, explore::GoalPolicyNames())) {
    throw InputError("unknown goal policy '" + e.goal_policy + "': expected one of " +
                     JoinNames(explore::GoalPolicyNames()));
  }
  if (!(e.local_slam.translation_weight >= 0.0) ||
      !std::isfinite(e.local_slam.translation_weight)) {
    throw InputError("explore.local_slam.translation_weight: expected a finite value >= 0");
  }
  if (!(e.local_slam.rotation_weight >= 0.0) || !std::isfinite(e.local_slam.rotation_weight)) {
    throw InputError("explore.local_slam.rotation_weight: expected a finite value >= 0");
  }
  if (!(e.local_slam.likelihood_field_sigma_m >= 0.0) ||
      !std::isfinite(e.local_slam.likelihood_field_sigma_m)) {
    throw InputError("explore.local_slam.likelihood_field_sigma_m: expected a finite value >= 0");
  }
  sim::CheckSimulatedRobotOptions(options.robot);
  frontier::Validate(options.frontier);
  try {
    explore::Validate(e.goals);
    explore::Validate(PlanningTraversability(options));
    explore::Validate(e.planner);
    explore::Validate(e.follower);
    explore::Validate(e.policy);
    slam::Validate(EffectiveSlamOptions(options));
  } catch (const std::invalid_argument& error) {
    throw InputError(std::string("explore: ") + error.what());
  }
  // The frontier detector decides which frontiers are reachable; with a
  // smaller inflation than the planner's narrowest clearance it offers goals
  // no plan reaches.
  const explore::TraversabilityOptions t = PlanningTraversability(options);
  const double planner_clearance =
      t.robot_radius_m + std::min(t.narrow_margin_m, t.safety_margin_m);
  if (!(e.frontier_inflation_radius_m >= 0.0) || !std::isfinite(e.frontier_inflation_radius_m)) {
    throw InputError("explore.frontier_inflation_radius_m: expected a finite value >= 0");
  }
  if (e.frontier_inflation_radius_m + 1e-9 < planner_clearance) {
    throw InputError("contradictory options: explore.frontier_inflation_radius_m (" +
                     FormatNumber(e.frontier_inflation_radius_m) +
                     ") is smaller than robot.radius_m + the smaller of explore.traversability."
                     "narrow_margin_m and safety_margin_m (" +
                     FormatNumber(planner_clearance) + ")");
  }
  if (e.follower.max_linear_speed_mps > options.robot.robot.max_linear_speed_mps + 1e-9 ||
      e.follower.max_angular_speed_radps > options.robot.robot.max_angular_speed_radps + 1e-9) {
    throw InputError("contradictory options: explore.follower speeds (" +
                     FormatNumber(e.follower.max_linear_speed_mps) + " m/s, " +
                     FormatNumber(e.follower.max_angular_speed_radps) +
                     " rad/s) exceed robot.max_linear_speed_mps / robot.max_angular_speed_radps (" +
                     FormatNumber(options.robot.robot.max_linear_speed_mps) + " m/s, " +
                     FormatNumber(options.robot.robot.max_angular_speed_radps) + " rad/s)");
  }
  CheckSensorRatesAtStep(e, options.robot);
  if (options.start && !options.start->allFinite()) {
    throw InputError("--start: expected finite coordinates");
  }
}

void CheckSensorRatesAtStep(const ExploreOptions& explore,
                            const sim::SimulatedRobotOptions& robot) {
  // The simulator samples at most one scan per step: a longer step drops scans.
  if (explore.dt_s > 1.0 / robot.scan_rate_hz * (1.0 + 1e-9)) {
    throw InputError("'explore.dt_s': expected at most one scan period (1 / robot.scan_rate_hz = " +
                     FormatNumber(1.0 / robot.scan_rate_hz) + " s), got " +
                     FormatNumber(explore.dt_s));
  }
  // Nor more than one odometry sample per step: a faster rate would be read as
  // the step rate, and the noise, drawn per sample, would not be what it says.
  if (robot.odometry_rate_hz > 1.0 / explore.dt_s * (1.0 + 1e-9)) {
    throw InputError(
        "'robot.odometry_rate_hz': expected at most one sample per simulation step "
        "(1 / explore.dt_s = " +
        FormatNumber(1.0 / explore.dt_s) + " Hz), got " + FormatNumber(robot.odometry_rate_hz));
  }
}

slam::SlamOptions EffectiveSlamOptions(const ExplorationOptions& options) {
  slam::SlamOptions slam = options.slam;
  const ExploreOptions::LocalSlam& l = options.explore.local_slam;
  slam.local.use_online_correlative_scan_matching = l.use_online_correlative_scan_matching;
  slam.local.ceres_scan_matcher.translation_weight = l.translation_weight;
  slam.local.ceres_scan_matcher.rotation_weight = l.rotation_weight;
  slam.local.ceres_scan_matcher.likelihood_field.sigma_m = l.likelihood_field_sigma_m;
  if (options.explore.synchronous_slam) {
    slam.pose_graph.synchronous = true;
    slam.pose_graph.synchronous_solve_delay_nodes = options.explore.solve_delay_nodes;
  }
  return slam;
}

}  // namespace scout::exploration
