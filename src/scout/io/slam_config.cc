#include "scout/io/slam_config.h"

#include <numbers>

namespace scout::io {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

using Bound = YamlSection::Bound;

// Reads 'key' (degrees) into 'radians', leaving it unchanged when absent.
void ReadPositiveDegrees(YamlSection& s, const std::string& key, double* radians) {
  double degrees = *radians / kRadPerDeg;
  s.ReadPositive(key, &degrees);
  *radians = degrees * kRadPerDeg;
}

// A search window to either side, in degrees: at most half a turn.
void ReadAngularWindow(YamlSection& s, const std::string& key, double* radians) {
  double degrees = *radians / kRadPerDeg;
  s.ReadInRange(key, &degrees, 0.0, 180.0, Bound::kInclusive, Bound::kInclusive);
  *radians = degrees * kRadPerDeg;
}

// The probability tables' limits (grid/probability_values.h).
void ReadGridProbability(YamlSection& s, const std::string& key, double* value) {
  s.ReadInRange(key, value, 0.1, 0.9, Bound::kInclusive, Bound::kInclusive);
}

void ReadAdaptiveVoxelFilter(YamlSection s, slam::AdaptiveVoxelFilterOptions* o) {
  s.ReadPositive("max_length_m", &o->max_length_m);
  s.ReadInt("min_num_points", &o->min_num_points, 1);
  s.ReadPositive("max_range_m", &o->max_range_m);
  s.RejectUnknownKeys();
}

// The likelihood field's keys of a scan matcher's section.
void ReadLikelihoodField(YamlSection& s, slam::LikelihoodFieldOptions* o) {
  s.ReadNonNegative("likelihood_field_sigma_m", &o->sigma_m);
  ReadGridProbability(s, "likelihood_field_occupied_probability", &o->occupied_probability);
}

// 'local': local SLAM's matcher, the only one given a motion prediction, so
// the only one whose section takes the prediction prior's keys.
void ReadCeresScanMatcher(YamlSection s, slam::CeresScanMatcherOptions* o, bool local) {
  s.ReadPositive("occupied_space_weight", &o->occupied_space_weight);
  s.ReadNonNegative("translation_weight", &o->translation_weight);
  s.ReadNonNegative("rotation_weight", &o->rotation_weight);
  if (local) {
    s.ReadNonNegative("prediction_translation_weight", &o->prediction_translation_weight);
    s.ReadNonNegative("prediction_max_constrained_fraction",
                      &o->prediction_max_constrained_fraction);
  }
  s.ReadInt("max_num_iterations", &o->max_num_iterations, 1);
  s.ReadInt("full_weight_num_points", &o->full_weight_num_points, 0);
  ReadGridProbability(s, "unknown_probability", &o->unknown_probability);
  ReadLikelihoodField(s, &o->likelihood_field);
  s.RejectUnknownKeys();
}

void ReadLocal(YamlSection s, slam::LocalSlamOptions* o) {
  {
    YamlSection r = s.Section("range_filter");
    r.ReadNonNegative("min_range_m", &o->range_filter.min_range_m);
    r.ReadPositive("max_range_m", &o->range_filter.max_range_m);
    r.ReadNonNegative("miss_ray_length_m", &o->range_filter.miss_ray_length_m);
    r.RejectUnknownKeys();
  }
  s.ReadPositive("voxel_filter_size_m", &o->voxel_filter_size_m);
  ReadAdaptiveVoxelFilter(s.Section("adaptive_voxel_filter"), &o->adaptive_voxel_filter);
  s.ReadBool("use_online_correlative_scan_matching", &o->use_online_correlative_scan_matching);
  s.ReadBool("use_odometry", &o->use_odometry);
  {
    YamlSection c = s.Section("real_time_correlative_scan_matcher");
    slam::RealTimeCorrelativeScanMatcherOptions& m = o->real_time_correlative_scan_matcher;
    c.ReadNonNegative("linear_search_window_m", &m.linear_search_window_m);
    ReadAngularWindow(c, "angular_search_window_deg", &m.angular_search_window_rad);
    c.ReadNonNegative("translation_delta_cost_weight", &m.translation_delta_cost_weight);
    c.ReadNonNegative("rotation_delta_cost_weight", &m.rotation_delta_cost_weight);
    ReadGridProbability(c, "unknown_probability", &m.unknown_probability);
    ReadLikelihoodField(c, &m.likelihood_field);
    c.ReadBool("initial_estimate_at_angular_edge", &m.initial_estimate_at_angular_edge);
    c.RejectUnknownKeys();
  }
  ReadAngularWindow(s, "second_search_after_turn_deg", &o->second_search_after_turn_rad);
  s.ReadNonNegative("second_search_min_gain", &o->second_search_min_gain);
  ReadCeresScanMatcher(s.Section("ceres_scan_matcher"), &o->ceres_scan_matcher, /*local=*/true);
  {
    YamlSection m = s.Section("motion_filter");
    m.ReadPositive("max_time_s", &o->motion_filter.max_time_s);
    m.ReadNonNegative("max_distance_m", &o->motion_filter.max_distance_m);
    ReadPositiveDegrees(m, "max_angle_deg", &o->motion_filter.max_angle_rad);
    m.RejectUnknownKeys();
  }
  {
    YamlSection m = s.Section("submaps");
    m.ReadPositive("resolution_m", &o->submaps.resolution_m);
    m.ReadInt("num_range_data", &o->submaps.num_range_data, 1);
    m.ReadNonNegative("max_travel_m", &o->submaps.max_travel_m);
    ReadHitMissProbabilities(m, &o->submaps.insertion);
    m.RejectUnknownKeys();
  }
  s.RejectUnknownKeys();
}

void ReadPoseGraph(YamlSection s, slam::PoseGraphOptions* o) {
  s.ReadInt("optimize_every_n_nodes", &o->optimize_every_n_nodes, 0);
  s.ReadNonNegative("optimize_every_travel_m", &o->optimize_every_travel_m);
  s.ReadBool("synchronous", &o->synchronous);
  s.ReadInt("synchronous_solve_delay_nodes", &o->synchronous_solve_delay_nodes, 0);
  s.ReadNonNegative("intra_submap_translation_weight", &o->intra_submap_translation_weight);
  s.ReadNonNegative("intra_submap_rotation_weight", &o->intra_submap_rotation_weight);
  ReadAdaptiveVoxelFilter(s.Section("loop_closure_voxel_filter"), &o->loop_closure_voxel_filter);
  s.ReadInt("skip_neighbour_submaps", &o->skip_neighbour_submaps, 0);
  s.ReadBool("search_windows_through_loop_closures", &o->search_windows_through_loop_closures);
  s.ReadNonNegative("loop_closure_chain_travel_m", &o->loop_closure_chain_travel_m);
  s.ReadBool("gate_loop_closures_by_chain", &o->gate_loop_closures_by_chain);
  s.ReadPositive("outlier_translation_m", &o->outlier_translation_m);
  s.ReadPositive("outlier_rotation_deg", &o->outlier_rotation_deg);
  s.ReadInt("max_outlier_rounds", &o->max_outlier_rounds, 0);
  {
    YamlSection c = s.Section("constraint_builder");
    slam::ConstraintBuilderOptions& b = o->constraint_builder;
    c.ReadPositive("sampling_ratio", &b.sampling_ratio);
    c.ReadNonNegative("sampling_phase", &b.sampling_phase);
    c.ReadNonNegative("max_sample_spacing_m", &b.max_sample_spacing_m);
    c.ReadPositive("max_constraint_distance_m", &b.max_constraint_distance_m);
    c.ReadPositive("min_score", &b.min_score);
    c.ReadNonNegative("min_score_fraction_of_own_scans", &b.min_score_fraction_of_own_scans);
    c.ReadNonNegative("min_overlap", &b.min_overlap);
    c.ReadNonNegative("wide_ambiguity_min_innovation_m", &b.wide_ambiguity_min_innovation_m);
    c.ReadPositive("wide_ambiguity_window_factor", &b.wide_ambiguity_window_factor);
    c.ReadPositive("wide_ambiguity_max_window_m", &b.wide_ambiguity_max_window_m);
    c.ReadNonNegative("near_match_max_innovation_m", &b.near_match_max_innovation_m);
    c.ReadNonNegative("near_match_min_score_fraction", &b.near_match_min_score_fraction);
    c.ReadNonNegative("min_search_window_m", &b.min_search_window_m);
    c.ReadNonNegative("search_window_per_travel", &b.search_window_per_travel);
    c.ReadNonNegative("min_angular_search_window_deg", &b.min_angular_search_window_deg);
    c.ReadNonNegative("angular_search_window_deg_per_m", &b.angular_search_window_deg_per_m);
    c.ReadInt("min_num_points", &b.min_num_points, 1);
    c.ReadNonNegative("max_see_through", &b.max_see_through);
    c.ReadNonNegative("see_through_slack_m", &b.see_through_slack_m);
    c.ReadNonNegative("loop_closure_translation_weight", &b.loop_closure_translation_weight);
    c.ReadNonNegative("loop_closure_rotation_weight", &b.loop_closure_rotation_weight);
    {
      YamlSection f = c.Section("fast_correlative_scan_matcher");
      f.ReadNonNegative("linear_search_window_m",
                        &b.fast_correlative_scan_matcher.linear_search_window_m);
      ReadAngularWindow(f, "angular_search_window_deg",
                        &b.fast_correlative_scan_matcher.angular_search_window_rad);
      f.ReadInt("branch_and_bound_depth", &b.fast_correlative_scan_matcher.branch_and_bound_depth,
                1);
      f.ReadNonNegative("ambiguity_radius_m", &b.fast_correlative_scan_matcher.ambiguity_radius_m);
      f.ReadNonNegative("ambiguity_score_margin",
                        &b.fast_correlative_scan_matcher.ambiguity_score_margin);
      f.RejectUnknownKeys();
    }
    ReadCeresScanMatcher(c.Section("ceres_scan_matcher"), &b.ceres_scan_matcher, /*local=*/false);
    c.RejectUnknownKeys();
  }
  {
    YamlSection p = s.Section("optimization_problem");
    slam::OptimizationProblemOptions& q = o->optimization_problem;
    p.ReadPositive("huber_scale", &q.huber_scale);
    p.ReadNonNegative("local_slam_pose_translation_weight", &q.local_slam_pose_translation_weight);
    p.ReadNonNegative("local_slam_pose_rotation_weight", &q.local_slam_pose_rotation_weight);
    p.ReadBool("use_odometry_constraints", &q.use_odometry_constraints);
    p.ReadNonNegative("odometry_translation_weight", &q.odometry_translation_weight);
    p.ReadNonNegative("odometry_rotation_weight", &q.odometry_rotation_weight);
    p.ReadInt("max_num_iterations", &q.max_num_iterations, 1);
    p.ReadInt("num_threads", &q.num_threads, 1);
    p.RejectUnknownKeys();
  }
  s.RejectUnknownKeys();
}

}  // namespace

void ReadSlamOptions(YamlSection section, slam::SlamOptions* options) {
  ReadLocal(section.Section("local"), &options->local);
  ReadPoseGraph(section.Section("pose_graph"), &options->pose_graph);
  section.ReadInt("submap_event_every_n_insertions", &options->submap_event_every_n_insertions, 1);
  section.RejectUnknownKeys();
}

void ReadHitMissProbabilities(YamlSection& s, grid::RangeDataInserterOptions* o) {
  // Within 0.001 of certainty, the odds tables underflow (1e-300 was an
  // internal error).
  s.ReadInRange("hit_probability", &o->hit_probability, 0.5, 0.999, Bound::kExclusive,
                Bound::kInclusive);
  s.ReadInRange("miss_probability", &o->miss_probability, 0.001, 0.5, Bound::kInclusive,
                Bound::kExclusive);
}

}  // namespace scout::io
