#include "scout/io/explore_config.h"

#include <numbers>
#include <stdexcept>

#include "scout/common/error.h"
#include "scout/explore/tour.h"

namespace scout::io {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

void ReadGoals(YamlSection s, explore::GoalManagerOptions* o) {
  s.ReadPositive("progress_timeout_s", &o->progress_timeout_s);
  s.ReadNonNegativeAtMost("progress_min_m", &o->progress_min_m, 100.0);
  s.ReadNonNegative("replan_interval_s", &o->replan_interval_s);
  s.ReadInt("max_plan_attempts", &o->max_plan_attempts, 1);
  s.ReadNonNegative("finish_after_empty_s", &o->finish_after_empty_s);
  s.ReadNonNegative("finish_with_frontier_after_s", &o->finish_with_frontier_after_s);
  s.ReadNonNegative("stuck_timeout_s", &o->stuck_timeout_s);
  s.ReadNonNegative("stuck_min_motion_m", &o->stuck_min_motion_m);
  s.ReadNonNegativeAtMost("back_up_distance_m", &o->back_up_distance_m, 10.0);
  s.ReadNonNegativeAtMost("back_up_speed_mps", &o->back_up_speed_mps, 10.0);
  s.ReadNonNegative("back_up_timeout_s", &o->back_up_timeout_s);
  s.ReadNonNegativeAtMost("back_up_look_behind_m", &o->back_up_look_behind_m, 5.0);
  s.ReadNonNegativeAtMost("back_up_trail_m", &o->back_up_trail_m, 100.0);
  s.ReadNonNegativeAtMost("back_up_trail_tolerance_m", &o->back_up_trail_tolerance_m, 10.0);
  s.ReadNonNegativeAtMost("retrace_m", &o->retrace_m, 100.0);
  s.ReadNonNegativeAtMost("retrace_clearance_m", &o->retrace_clearance_m, 1.0);
  s.ReadNonNegativeAtMost("last_resort_retrace_m", &o->last_resort_retrace_m, 100.0);
  s.ReadNonNegativeAtMost("last_resort_confined_radius_m", &o->last_resort_confined_radius_m,
                          100.0);
  s.ReadNonNegative("last_resort_confined_s", &o->last_resort_confined_s);
  s.ReadInt("max_last_resorts", &o->max_last_resorts, 0);
  s.ReadNonNegativeAtMost("close_stuck_passage_radius_m", &o->close_stuck_passage_radius_m, 10.0);
  s.ReadNonNegativeAtMost("goal_frontier_radius_m", &o->goal_frontier_radius_m, 10.0);
  s.ReadNonNegative("goal_switch_margin", &o->goal_switch_margin);
  s.ReadNonNegativeAtMost("goal_match_radius_m", &o->goal_match_radius_m, 20.0);
  s.ReadNonNegativeAtMost("max_stand_off_m", &o->max_stand_off_m, 10.0);
  s.ReadNonNegativeAtMost("scan_check_radius_m", &o->scan_check_radius_m, 1.0);
  s.ReadNonNegativeAtMost("scan_check_memory_s", &o->scan_check_memory_s, 600.0);
  s.ReadNonNegativeAtMost("stand_off_unknown_margin_m", &o->stand_off_unknown_margin_m, 1.0);
  s.ReadBool("return_to_start", &o->return_to_start);
  {
    YamlSection g = s.Section("guard");
    g.ReadNonNegativeAtMost("clearance_m", &o->guard.clearance_m, 1.0);
    g.ReadNonNegativeAtMost("horizon_s", &o->guard.horizon_s, 10.0);
    g.ReadNonNegativeAtMost("steer_max_curvature_per_m", &o->guard.steer_max_curvature_per_m,
                            100.0);
    g.ReadNonNegativeAtMost("steer_step_per_m", &o->guard.steer_step_per_m, 100.0);
    g.ReadNonNegativeAtMost("memory_s", &o->guard.memory_s, 600.0);
    g.ReadBool("predict_motion", &o->guard.predict_motion);
    g.ReadNonNegativeAtMost("stop_turn_radps", &o->guard.stop_turn_radps, 10.0);
    g.RejectUnknownKeys();
  }
  {
    YamlSection f = s.Section("failed_goals");
    f.ReadNonNegativeAtMost("blacklist_radius_m", &o->failed_goals.blacklist_radius_m, 10.0);
    f.ReadPositiveAtMost("retry_radius_m", &o->failed_goals.retry_radius_m, 10.0);
    f.ReadNonNegative("retry_known_area_change_m2", &o->failed_goals.retry_known_area_change_m2);
    f.ReadInt("max_failures", &o->failed_goals.max_failures, 0);
    f.RejectUnknownKeys();
  }
  s.RejectUnknownKeys();
}

void ReadFollower(YamlSection s, explore::PathFollowerOptions* o) {
  s.ReadPositiveAtMost("lookahead_m", &o->lookahead_m, 10.0);
  s.ReadPositive("max_linear_speed_mps", &o->max_linear_speed_mps);
  s.ReadPositive("max_angular_speed_radps", &o->max_angular_speed_radps);
  double heading_deg = o->rotate_in_place_heading_rad / kRadiansPerDegree;
  s.ReadInRange("rotate_in_place_heading_deg", &heading_deg, 0.0, 180.0,
                YamlSection::Bound::kInclusive, YamlSection::Bound::kInclusive);
  o->rotate_in_place_heading_rad = heading_deg * kRadiansPerDegree;
  s.ReadPositive("rotate_gain_per_s", &o->rotate_gain_per_s);
  s.ReadPositiveAtMost("goal_tolerance_m", &o->goal_tolerance_m, 5.0);
  s.ReadNonNegativeAtMost("slow_down_distance_m", &o->slow_down_distance_m, 10.0);
  s.ReadNonNegative("min_linear_speed_mps", &o->min_linear_speed_mps);
  s.RejectUnknownKeys();
}

void ReadPolicy(YamlSection s, explore::GoalPolicyOptions* o) {
  {
    YamlSection n = s.Section("navigation");
    explore::NavigationPointOptions& v = o->navigation;
    n.ReadPositiveAtMost("bandwidth_m", &v.mean_shift.bandwidth_m, 20.0);
    n.ReadNonNegativeAtMost("seed_bin_m", &v.mean_shift.seed_bin_m, 10.0);
    n.ReadPositiveAtMost("convergence_m", &v.mean_shift.convergence_m, 1.0);
    n.ReadInt("max_iterations", &v.mean_shift.max_iterations, 1);
    n.ReadNonNegativeAtMost("connectivity_margin_m", &v.connectivity_margin_m, 20.0);
    n.ReadPositiveAtMost("info_radius_m", &v.info_radius_m, 10.0);
    n.ReadBool("outside_map_is_unknown", &v.outside_map_is_unknown);
    n.ReadNonNegativeAtMost("info_visible_range_m", &v.info_visible_range_m,
                            explore::kMaxInfoVisibleRange_m);
    n.ReadNonNegative("info_multiplier", &v.info_multiplier);
    n.ReadNonNegativeAtMost("hysteresis_radius_m", &v.hysteresis_radius_m, 20.0);
    n.ReadPositive("hysteresis_gain", &v.hysteresis_gain);
    n.ReadInt("tour_points", &v.tour_points, 0, explore::kMaxTourPoints);
    n.RejectUnknownKeys();
  }
  {
    YamlSection l = s.Section("explore_lite");
    l.ReadNonNegative("potential_scale", &o->explore_lite.potential_scale);
    l.ReadNonNegative("gain_scale", &o->explore_lite.gain_scale);
    l.ReadNonNegativeAtMost("min_frontier_size_m", &o->explore_lite.min_frontier_size_m, 100.0);
    l.RejectUnknownKeys();
  }
  s.RejectUnknownKeys();
}

// Converts a module's std::invalid_argument into an InputError naming the file
// and the section the key belongs to.
template <typename Options>
void Check(const Options& options, const std::string& file, const std::string& section) {
  try {
    explore::Validate(options);
  } catch (const std::invalid_argument& e) {
    throw InputError(file + ": " + section + ": " + e.what());
  }
}

}  // namespace

void ReadExploreOptions(YamlSection s, exploration::ExploreOptions* o) {
  // At least a millisecond: 1e-9 would take years of wall time per simulated second.
  s.ReadInRange("dt_s", &o->dt_s, 0.001, 1.0, YamlSection::Bound::kInclusive,
                YamlSection::Bound::kInclusive);
  s.ReadPositive("max_sim_time_s", &o->max_sim_time_s);
  s.ReadPositive("no_progress_timeout_s", &o->no_progress_timeout_s);
  s.ReadNonNegative("min_map_gain_m2", &o->min_map_gain_m2);
  s.ReadNonNegative("complete_max_reachable_frontier_m", &o->complete_max_reachable_frontier_m);
  s.ReadPositive("map_update_interval_s", &o->map_update_interval_s);
  s.ReadPositive("coverage_interval_s", &o->coverage_interval_s);
  double turn_deg = o->initial_turn_rad / kRadiansPerDegree;
  s.ReadNonNegativeAtMost("initial_turn_deg", &turn_deg, 3600.0);
  o->initial_turn_rad = turn_deg * kRadiansPerDegree;
  s.ReadBool("evaluate_frontier", &o->evaluate_frontier);
  s.ReadBool("synchronous_slam", &o->synchronous_slam);
  s.ReadInt("solve_delay_nodes", &o->solve_delay_nodes, 0);
  {
    YamlSection l = s.Section("local_slam");
    l.ReadBool("use_online_correlative_scan_matching",
               &o->local_slam.use_online_correlative_scan_matching);
    l.ReadNonNegative("translation_weight", &o->local_slam.translation_weight);
    l.ReadNonNegative("rotation_weight", &o->local_slam.rotation_weight);
    l.ReadNonNegative("likelihood_field_sigma_m", &o->local_slam.likelihood_field_sigma_m);
    l.RejectUnknownKeys();
  }
  s.ReadNonNegativeAtMost("frontier_inflation_radius_m", &o->frontier_inflation_radius_m, 5.0);
  s.ReadPoints("boundary", &o->boundary);
  ReadGoals(s.Section("goals"), &o->goals);
  {
    YamlSection t = s.Section("traversability");
    t.ReadNonNegativeAtMost("safety_margin_m", &o->traversability.safety_margin_m, 5.0);
    t.ReadBool("unknown_traversable", &o->traversability.unknown_traversable);
    t.ReadNonNegativeAtMost("goal_snap_radius_m", &o->traversability.goal_snap_radius_m, 5.0);
    t.ReadNonNegativeAtMost("narrow_margin_m", &o->traversability.narrow_margin_m, 5.0);
    t.ReadNonNegativeAtMost("narrow_cost_factor", &o->traversability.narrow_cost_factor, 1000.0);
    t.ReadNonNegativeAtMost("escape_radius_m", &o->traversability.escape_radius_m, 10.0);
    t.ReadNonNegativeAtMost("driven_width_m", &o->traversability.driven_width_m, 5.0);
    t.ReadNonNegativeAtMost("driven_max_gap_m", &o->traversability.driven_max_gap_m, 100.0);
    t.RejectUnknownKeys();
  }
  {
    YamlSection p = s.Section("planner");
    p.ReadNonNegativeAtMost("clearance_weight", &o->planner.clearance_weight, 1000.0);
    p.ReadPositiveAtMost("clearance_band_m", &o->planner.clearance_band_m, 10.0);
    p.ReadBool("shortcut", &o->planner.shortcut);
    p.RejectUnknownKeys();
  }
  ReadFollower(s.Section("follower"), &o->follower);
  ReadPolicy(s.Section("policy"), &o->policy);
  s.RejectUnknownKeys();
}

void ReadLidarOptions(YamlSection l, sim::LidarOptions* o) {
  // No ray is longer than sensor::kMaxRayLength_m (200 m).
  l.ReadPositiveAtMost("range_max_m", &o->range_max_m, 200.0);
  l.ReadNonNegative("range_min_m", &o->range_min_m);
  l.ReadInRange("fov_deg", &o->fov_deg, 0.0, 360.0, YamlSection::Bound::kExclusive,
                YamlSection::Bound::kInclusive);
  // 0.01 degree apart over a full turn; more only exhausts memory.
  l.ReadInt("beams", &o->beams, 2, 36000);
  l.ReadNonNegativeAtMost("range_noise_stddev_m", &o->range_noise_stddev_m, 1.0);
  l.ReadInRange("dropout_probability", &o->dropout_probability, 0.0, 1.0,
                YamlSection::Bound::kInclusive, YamlSection::Bound::kInclusive);
  l.RejectUnknownKeys();
}

void ReadRobotOptions(YamlSection s, sim::SimulatedRobotOptions* o) {
  s.ReadPositive("radius_m", &o->robot.radius_m);
  s.ReadPositive("max_linear_speed_mps", &o->robot.max_linear_speed_mps);
  s.ReadPositive("max_angular_speed_radps", &o->robot.max_angular_speed_radps);
  s.ReadPositive("max_linear_accel_mps2", &o->robot.max_linear_accel_mps2);
  s.ReadPositive("max_angular_accel_radps2", &o->robot.max_angular_accel_radps2);
  s.ReadPositive("collision_substep_cells", &o->robot.collision_substep_cells);
  s.ReadPositive("scan_rate_hz", &o->scan_rate_hz);
  s.ReadPositive("odometry_rate_hz", &o->odometry_rate_hz);
  double heading_deg = o->start_heading_rad / kRadiansPerDegree;
  s.ReadDouble("start_heading_deg", &heading_deg);
  o->start_heading_rad = heading_deg * kRadiansPerDegree;
  ReadLidarOptions(s.Section("lidar"), &o->lidar);
  {
    YamlSection d = s.Section("odometry");
    d.ReadNonNegative("trans_per_trans", &o->odometry.trans_per_trans);
    d.ReadNonNegative("trans_per_rot", &o->odometry.trans_per_rot);
    d.ReadNonNegative("rot_per_rot", &o->odometry.rot_per_rot);
    d.ReadNonNegative("rot_per_trans", &o->odometry.rot_per_trans);
    d.RejectUnknownKeys();
  }
  s.RejectUnknownKeys();
}

void ValidateExploreAndRobot(const exploration::ExploreOptions& explore,
                             const sim::SimulatedRobotOptions& robot, const std::string& file) {
  try {
    sim::CheckSimulatedRobotOptions(robot);
  } catch (const InputError& e) {
    throw InputError(file + ": " + e.what());
  }
  try {
    exploration::CheckExplorationBoundary(explore.boundary);
  } catch (const InputError& e) {
    throw InputError(file + ": " + e.what());
  }
  try {
    exploration::CheckSensorRatesAtStep(explore, robot);
  } catch (const InputError& e) {
    throw InputError(file + ": " + e.what());
  }
  Check(explore.goals, file, "explore.goals");
  Check(explore.traversability, file, "explore.traversability");
  Check(explore.planner, file, "explore.planner");
  Check(explore.follower, file, "explore.follower");
  Check(explore.policy, file, "explore.policy");
}

}  // namespace scout::io
