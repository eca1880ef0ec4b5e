#include "scout/io/config.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scout/common/atomic_file.h"
#include "scout/common/error.h"
#include "scout/io/options_file_test_fixture.h"

namespace scout::io {
namespace {

namespace fs = std::filesystem;

using ConfigTest = testing::OptionsFileTest;

TEST_F(ConfigTest, DefaultFileMatchesTheBuiltInDefaults) {
  const ScoutConfig c = LoadConfig(fs::path(SCOUT_SOURCE_DIR) / "config" / "default.yaml");
  const ScoutConfig d;
  EXPECT_DOUBLE_EQ(c.frontier.inflation_radius_m, d.frontier.inflation_radius_m);
  EXPECT_DOUBLE_EQ(c.frontier.epsilon_m, d.frontier.epsilon_m);
  EXPECT_DOUBLE_EQ(c.frontier.exact_slack_m, d.frontier.exact_slack_m);
  EXPECT_EQ(c.synthetic.scans_per_submap, d.synthetic.scans_per_submap);
  EXPECT_NEAR(c.synthetic.scan_spacing_rad, d.synthetic.scan_spacing_rad, 1e-12);
  EXPECT_DOUBLE_EQ(c.synthetic.lidar.range_max_m, d.synthetic.lidar.range_max_m);
  EXPECT_DOUBLE_EQ(c.synthetic.corrections.newest_jitter_m,
                   d.synthetic.corrections.newest_jitter_m);
}

TEST_F(ConfigTest, SlamSectionOfTheDefaultFileMatchesTheBuiltInDefaults) {
  const slam::SlamOptions c =
      LoadConfig(fs::path(SCOUT_SOURCE_DIR) / "config" / "default.yaml").slam;
  const slam::SlamOptions d;
  EXPECT_EQ(c.submap_event_every_n_insertions, d.submap_event_every_n_insertions);
  EXPECT_DOUBLE_EQ(c.local.range_filter.max_range_m, d.local.range_filter.max_range_m);
  EXPECT_DOUBLE_EQ(c.local.range_filter.miss_ray_length_m, d.local.range_filter.miss_ray_length_m);
  EXPECT_DOUBLE_EQ(c.local.voxel_filter_size_m, d.local.voxel_filter_size_m);
  EXPECT_EQ(c.local.adaptive_voxel_filter.min_num_points,
            d.local.adaptive_voxel_filter.min_num_points);
  EXPECT_EQ(c.local.use_online_correlative_scan_matching,
            d.local.use_online_correlative_scan_matching);
  EXPECT_EQ(c.local.use_odometry, d.local.use_odometry);
  EXPECT_NEAR(c.local.real_time_correlative_scan_matcher.angular_search_window_rad,
              d.local.real_time_correlative_scan_matcher.angular_search_window_rad, 1e-12);
  EXPECT_EQ(c.local.real_time_correlative_scan_matcher.initial_estimate_at_angular_edge,
            d.local.real_time_correlative_scan_matcher.initial_estimate_at_angular_edge);
  EXPECT_NEAR(c.local.second_search_after_turn_rad, d.local.second_search_after_turn_rad, 1e-12);
  EXPECT_DOUBLE_EQ(c.local.second_search_min_gain, d.local.second_search_min_gain);
  EXPECT_DOUBLE_EQ(c.local.ceres_scan_matcher.occupied_space_weight,
                   d.local.ceres_scan_matcher.occupied_space_weight);
  EXPECT_EQ(c.local.ceres_scan_matcher.full_weight_num_points,
            d.local.ceres_scan_matcher.full_weight_num_points);
  EXPECT_DOUBLE_EQ(c.local.ceres_scan_matcher.translation_weight,
                   d.local.ceres_scan_matcher.translation_weight);
  EXPECT_DOUBLE_EQ(c.local.ceres_scan_matcher.rotation_weight,
                   d.local.ceres_scan_matcher.rotation_weight);
  EXPECT_DOUBLE_EQ(c.local.ceres_scan_matcher.prediction_translation_weight,
                   d.local.ceres_scan_matcher.prediction_translation_weight);
  EXPECT_DOUBLE_EQ(c.local.ceres_scan_matcher.prediction_max_constrained_fraction,
                   d.local.ceres_scan_matcher.prediction_max_constrained_fraction);
  EXPECT_NEAR(c.local.motion_filter.max_angle_rad, d.local.motion_filter.max_angle_rad, 1e-12);
  EXPECT_DOUBLE_EQ(c.local.motion_filter.max_distance_m, d.local.motion_filter.max_distance_m);
  EXPECT_EQ(c.local.submaps.num_range_data, d.local.submaps.num_range_data);
  EXPECT_DOUBLE_EQ(c.local.submaps.resolution_m, d.local.submaps.resolution_m);
  EXPECT_EQ(c.pose_graph.optimize_every_n_nodes, d.pose_graph.optimize_every_n_nodes);
  EXPECT_EQ(c.pose_graph.synchronous, d.pose_graph.synchronous);
  EXPECT_DOUBLE_EQ(c.pose_graph.intra_submap_translation_weight,
                   d.pose_graph.intra_submap_translation_weight);
  EXPECT_DOUBLE_EQ(c.pose_graph.constraint_builder.sampling_ratio,
                   d.pose_graph.constraint_builder.sampling_ratio);
  EXPECT_DOUBLE_EQ(c.pose_graph.constraint_builder.sampling_phase,
                   d.pose_graph.constraint_builder.sampling_phase);
  EXPECT_DOUBLE_EQ(c.pose_graph.constraint_builder.min_score,
                   d.pose_graph.constraint_builder.min_score);
  EXPECT_DOUBLE_EQ(c.local.ceres_scan_matcher.unknown_probability,
                   d.local.ceres_scan_matcher.unknown_probability);
  EXPECT_DOUBLE_EQ(c.local.real_time_correlative_scan_matcher.unknown_probability,
                   d.local.real_time_correlative_scan_matcher.unknown_probability);
  EXPECT_DOUBLE_EQ(c.local.ceres_scan_matcher.likelihood_field.sigma_m,
                   d.local.ceres_scan_matcher.likelihood_field.sigma_m);
  EXPECT_DOUBLE_EQ(c.local.ceres_scan_matcher.likelihood_field.occupied_probability,
                   d.local.ceres_scan_matcher.likelihood_field.occupied_probability);
  EXPECT_DOUBLE_EQ(c.local.real_time_correlative_scan_matcher.likelihood_field.sigma_m,
                   d.local.real_time_correlative_scan_matcher.likelihood_field.sigma_m);
  EXPECT_DOUBLE_EQ(c.pose_graph.constraint_builder.ceres_scan_matcher.likelihood_field.sigma_m,
                   d.pose_graph.constraint_builder.ceres_scan_matcher.likelihood_field.sigma_m);
  const slam::ConstraintBuilderOptions& cb = c.pose_graph.constraint_builder;
  const slam::ConstraintBuilderOptions& db = d.pose_graph.constraint_builder;
  EXPECT_DOUBLE_EQ(cb.min_overlap, db.min_overlap);
  EXPECT_DOUBLE_EQ(cb.max_see_through, db.max_see_through);
  EXPECT_DOUBLE_EQ(cb.see_through_slack_m, db.see_through_slack_m);
  EXPECT_DOUBLE_EQ(cb.min_search_window_m, db.min_search_window_m);
  EXPECT_DOUBLE_EQ(cb.search_window_per_travel, db.search_window_per_travel);
  EXPECT_DOUBLE_EQ(cb.min_angular_search_window_deg, db.min_angular_search_window_deg);
  EXPECT_DOUBLE_EQ(cb.angular_search_window_deg_per_m, db.angular_search_window_deg_per_m);
  EXPECT_EQ(cb.min_num_points, db.min_num_points);
  EXPECT_DOUBLE_EQ(cb.near_match_max_innovation_m, db.near_match_max_innovation_m);
  EXPECT_DOUBLE_EQ(cb.near_match_min_score_fraction, db.near_match_min_score_fraction);
  EXPECT_DOUBLE_EQ(c.pose_graph.outlier_translation_m, d.pose_graph.outlier_translation_m);
  EXPECT_DOUBLE_EQ(c.pose_graph.outlier_rotation_deg, d.pose_graph.outlier_rotation_deg);
  EXPECT_EQ(c.pose_graph.max_outlier_rounds, d.pose_graph.max_outlier_rounds);
  EXPECT_DOUBLE_EQ(cb.fast_correlative_scan_matcher.ambiguity_radius_m,
                   db.fast_correlative_scan_matcher.ambiguity_radius_m);
  EXPECT_DOUBLE_EQ(cb.fast_correlative_scan_matcher.ambiguity_score_margin,
                   db.fast_correlative_scan_matcher.ambiguity_score_margin);
  EXPECT_DOUBLE_EQ(cb.ceres_scan_matcher.unknown_probability,
                   db.ceres_scan_matcher.unknown_probability);
  EXPECT_DOUBLE_EQ(c.pose_graph.constraint_builder.loop_closure_translation_weight,
                   d.pose_graph.constraint_builder.loop_closure_translation_weight);
  EXPECT_EQ(c.pose_graph.constraint_builder.fast_correlative_scan_matcher.branch_and_bound_depth,
            d.pose_graph.constraint_builder.fast_correlative_scan_matcher.branch_and_bound_depth);
  EXPECT_DOUBLE_EQ(c.pose_graph.constraint_builder.ceres_scan_matcher.occupied_space_weight,
                   d.pose_graph.constraint_builder.ceres_scan_matcher.occupied_space_weight);
  EXPECT_DOUBLE_EQ(c.pose_graph.optimization_problem.huber_scale,
                   d.pose_graph.optimization_problem.huber_scale);
  EXPECT_EQ(c.pose_graph.optimization_problem.max_num_iterations,
            d.pose_graph.optimization_problem.max_num_iterations);
}

TEST_F(ConfigTest, SlamValuesOverrideDefaultsAndErrorsNameTheKey) {
  const ScoutConfig c =
      LoadConfig(Write("slam:\n  local:\n    submaps:\n      num_range_data: 150\n"
                       "    motion_filter:\n      max_angle_deg: 2\n"));
  EXPECT_EQ(c.slam.local.submaps.num_range_data, 150);
  EXPECT_FALSE(
      LoadConfig(Write("slam:\n  local:\n    use_odometry: false\n")).slam.local.use_odometry);
  EXPECT_NEAR(c.slam.local.motion_filter.max_angle_rad, 2.0 * M_PI / 180.0, 1e-12);
  EXPECT_DOUBLE_EQ(
      LoadConfig(
          Write("slam:\n  pose_graph:\n    constraint_builder:\n      sampling_phase: 0.4\n"))
          .slam.pose_graph.constraint_builder.sampling_phase,
      0.4);
  const ScoutConfig near = LoadConfig(
      Write("slam:\n  pose_graph:\n    constraint_builder:\n      near_match_max_innovation_m: 0\n"
            "      near_match_min_score_fraction: 0.9\n"));
  EXPECT_EQ(near.slam.pose_graph.constraint_builder.near_match_max_innovation_m, 0.0);
  EXPECT_DOUBLE_EQ(near.slam.pose_graph.constraint_builder.near_match_min_score_fraction, 0.9);
  std::string e = ErrorOf(
      "slam:\n  pose_graph:\n    constraint_builder:\n      near_match_min_score_fraction: 1.5\n");
  EXPECT_NE(e.find("near_match_min_score_fraction"), std::string::npos) << e;
  e = ErrorOf("slam:\n  pose_graph:\n    constraint_builder:\n      min_scor: 0.6\n");
  EXPECT_NE(e.find("slam.pose_graph.constraint_builder.min_scor"), std::string::npos) << e;
  // Out-of-range values caught by the module's own validation still name the file.
  e = ErrorOf("slam:\n  local:\n    submaps:\n      hit_probability: 0.4\n");
  EXPECT_NE(e.find("options.yaml"), std::string::npos) << e;
  EXPECT_NE(e.find("slam.local.submaps.hit_probability"), std::string::npos) << e;
  EXPECT_NE(e.find("(0.5, 0.999]"), std::string::npos) << e;
  // Windows in degrees are checked, and named, in degrees.
  e = ErrorOf(
      "slam:\n  local:\n    real_time_correlative_scan_matcher:\n"
      "      angular_search_window_deg: 400\n");
  EXPECT_NE(e.find("slam.local.real_time_correlative_scan_matcher.angular_search_window_deg"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("[0, 180]"), std::string::npos) << e;
  e = ErrorOf("slam:\n  local:\n    range_filter:\n      min_range_m: 20\n");
  EXPECT_NE(e.find("slam.local.range_filter.max_range_m"), std::string::npos) << e;
  // The likelihood field: read, and checked.
  const ScoutConfig field = LoadConfig(
      Write("slam:\n  local:\n    ceres_scan_matcher:\n      likelihood_field_sigma_m: 0\n"
            "      likelihood_field_occupied_probability: 0.6\n"));
  EXPECT_EQ(field.slam.local.ceres_scan_matcher.likelihood_field.sigma_m, 0.0);
  EXPECT_DOUBLE_EQ(field.slam.local.ceres_scan_matcher.likelihood_field.occupied_probability, 0.6);
  EXPECT_DOUBLE_EQ(LoadConfig(Write("slam:\n  local:\n    real_time_correlative_scan_matcher:\n"
                                    "      likelihood_field_sigma_m: 0.06\n"))
                       .slam.local.real_time_correlative_scan_matcher.likelihood_field.sigma_m,
                   0.06);
  for (const bool edge : {false, true}) {
    EXPECT_EQ(LoadConfig(Write(std::string("slam:\n  local:\n    "
                                           "real_time_correlative_scan_matcher:\n"
                                           "      initial_estimate_at_angular_edge: ") +
                               (edge ? "true" : "false") + "\n"))
                  .slam.local.real_time_correlative_scan_matcher.initial_estimate_at_angular_edge,
              edge);
  }
  e = ErrorOf(
      "slam:\n  local:\n    real_time_correlative_scan_matcher:\n"
      "      initial_estimate_at_angular_edge: 3\n");
  EXPECT_NE(
      e.find("slam.local.real_time_correlative_scan_matcher.initial_estimate_at_angular_edge"),
      std::string::npos)
      << e;
  e = ErrorOf(
      "slam:\n  local:\n    real_time_correlative_scan_matcher:\n"
      "      likelihood_field_occupied_probability: 1.5\n");
  EXPECT_NE(e.find("slam.local.real_time_correlative_scan_matcher.likelihood_field_occupied_"
                   "probability"),
            std::string::npos)
      << e;
  // The prior toward the motion prediction: local SLAM's matcher only, the
  // one given a prediction.
  const ScoutConfig prior = LoadConfig(
      Write("slam:\n  local:\n    ceres_scan_matcher:\n      prediction_translation_weight: 5\n"
            "      prediction_max_constrained_fraction: 0.05\n"));
  EXPECT_DOUBLE_EQ(prior.slam.local.ceres_scan_matcher.prediction_translation_weight, 5.0);
  EXPECT_DOUBLE_EQ(prior.slam.local.ceres_scan_matcher.prediction_max_constrained_fraction, 0.05);
  for (const auto& [yaml, expected] :
       {std::pair<const char*, const char*>{
            "slam:\n  pose_graph:\n    constraint_builder:\n      ceres_scan_matcher:\n"
            "        prediction_translation_weight: 5\n",
            "slam.pose_graph.constraint_builder.ceres_scan_matcher.prediction_translation_weight"},
        {"slam:\n  local:\n    ceres_scan_matcher:\n      prediction_max_constrained_fraction: 2\n",
         "slam.local.ceres_scan_matcher.prediction_max_constrained_fraction must be in [0, 1]"}}) {
    e = ErrorOf(yaml);
    EXPECT_NE(e.find(expected), std::string::npos) << e;
  }
  // The second search after a surprising match: its threshold and gain.
  const ScoutConfig second =
      LoadConfig(Write("slam:\n  local:\n    second_search_after_turn_deg: 0\n"
                       "    second_search_min_gain: 0.1\n"));
  EXPECT_EQ(second.slam.local.second_search_after_turn_rad, 0.0);
  EXPECT_DOUBLE_EQ(second.slam.local.second_search_min_gain, 0.1);
  e = ErrorOf("slam:\n  local:\n    second_search_after_turn_deg: 200\n");
  EXPECT_NE(e.find("slam.local.second_search_after_turn_deg"), std::string::npos) << e;
  e = ErrorOf("slam:\n  local:\n    second_search_min_gain: -0.1\n");
  EXPECT_NE(e.find("slam.local.second_search_min_gain"), std::string::npos) << e;
  e = ErrorOf("slam:\n  local:\n    ceres_scan_matcher:\n      likelihood_field_sigma_m: -1\n");
  EXPECT_NE(e.find("slam.local.ceres_scan_matcher.likelihood_field_sigma_m"), std::string::npos)
      << e;
  e = ErrorOf(
      "slam:\n  local:\n    ceres_scan_matcher:\n"
      "      likelihood_field_occupied_probability: 0.95\n");
  EXPECT_NE(e.find("slam.local.ceres_scan_matcher.likelihood_field_occupied_probability"),
            std::string::npos)
      << e;
}

TEST_F(ConfigTest, ExtremeValuesAreErrorsNamingTheKeyNotRunawayRuns) {
  // Each was an internal error, a hang or gigabytes of memory before it had a bound.
  const std::pair<const char*, const char*> cases[] = {
      {"frontier:\n  inflation_radius_m: 100000\n",
       "'frontier.inflation_radius_m': expected a number in [0, 5]"},
      {"slam:\n  local:\n    submaps:\n      miss_probability: 1e-300\n",
       "'slam.local.submaps.miss_probability': expected a number in [0.001, 0.5)"},
      {"synthetic:\n  insertion:\n    miss_probability: 1e-300\n",
       "'synthetic.insertion.miss_probability'"},
      {"synthetic:\n  scan_spacing_m: 1e-300\n", "'synthetic.scan_spacing_m': expected"},
      {"synthetic:\n  tour:\n    smoothing_iterations: 100000\n",
       "'synthetic.tour.smoothing_iterations': expected an integer from 0 to 1000"},
      {"synthetic:\n  corrections:\n    drift_heading_rad_per_sqrt_m: 1e300\n",
       "'synthetic.corrections.drift_heading_rad_per_sqrt_m': expected a number in [0, 1]"},
      {"synthetic:\n  lidar:\n    range_max_m: 100000\n",
       "'synthetic.lidar.range_max_m': expected a number in (0, 200]"},
      {"slam:\n  pose_graph:\n    optimization_problem:\n      num_threads: 100000\n",
       "'slam.pose_graph.optimization_problem.num_threads': expected 1 to 64"},
      {"slam:\n  pose_graph:\n    constraint_builder:\n      sampling_ratio: 2\n",
       "'slam.pose_graph.constraint_builder.sampling_ratio': expected a value in (0, 1], got 2"},
      {"slam:\n  pose_graph:\n    constraint_builder:\n      sampling_phase: 1\n",
       "'slam.pose_graph.constraint_builder.sampling_phase': expected a value in [0, 1), got 1"},
      {"slam:\n  local:\n    range_filter:\n      min_range_m: 1e300\n",
       "range_filter.min_range_m must be in [0, 200] (m), got 1e+300"}};
  for (const auto& [yaml, expected] : cases) {
    const std::string error = ErrorOf(yaml);
    EXPECT_NE(error.find(expected), std::string::npos) << yaml << ": " << error;
  }
}

TEST_F(ConfigTest, ARepeatedOrNonScalarKeyIsAnError) {
  // yaml-cpp keeps both entries of a repeated key; only the first would be read.
  ExpectErrors(
      {{"frontier:\n  epsilon_m: 0.1\n  epsilon_m: 0.2\n", "options.yaml:3"},
       {"frontier:\n  epsilon_m: 0.1\n  epsilon_m: 0.2\n", "'frontier.epsilon_m' given twice"},
       {"frontier:\n  epsilon_m: 0.1\nfrontier:\n  epsilon_m: 0.3\n", "'frontier' given twice"},
       {"frontier:\n  ? [a, b]\n  : 1\n", "expected option names as keys"},
       // yaml-cpp's LoadFile reads the first document only.
       {"frontier:\n  epsilon_m: 0.1\n---\nfrontier:\n  epsilon_m: 0.3\n",
        "options.yaml: holds 2 YAML documents"}});
}

TEST_F(ConfigTest, SizesThatWouldExhaustMemoryOrTimeAreErrors) {
  // Each of these used to fail with an internal error or never finish a scan.
  ExpectErrors({{"slam:\n  local:\n    submaps:\n      resolution_m: 1e-9\n",
                 "slam.local.submaps.resolution_m must be in [0.01, 1]"},
                {"slam:\n  local:\n    range_filter:\n      miss_ray_length_m: 1e9\n",
                 "slam.local.range_filter.miss_ray_length_m must be in [0, 200]"},
                {"slam:\n  local:\n    range_filter:\n      max_range_m: 1e5\n",
                 "slam.local.range_filter.max_range_m must be at most 200"},
                {"slam:\n  local:\n    real_time_correlative_scan_matcher:\n"
                 "      linear_search_window_m: 1000\n",
                 "linear_search_window_m must be in [0, 2]"},
                {"synthetic:\n  resolution_m: 1e-9\n", "synthetic.resolution_m"}});
}

TEST_F(ConfigTest, SyntheticOptionsAreCheckedWhenTheFileLoads) {
  ExpectErrors(
      {{"synthetic:\n  insertion:\n    hit_probability: 0.3\n",
        "synthetic.insertion.hit_probability"},
       {"synthetic:\n  corrections:\n    pull_decay_per_submap: 1.5\n",
        "options.yaml: synthetic.corrections.pull_decay_per_submap"},
       {"synthetic:\n  tour:\n    waypoint_clearance_m: 0.1\n",
        "options.yaml: synthetic.tour.waypoint_clearance_m"},
       {"synthetic:\n  lidar:\n    range_min_m: 9\n", "options.yaml: synthetic.lidar.range_min_m"},
       {"synthetic:\n  range_filter:\n    max_range_m: 0.5\n    min_range_m: 1\n",
        "options.yaml: synthetic.range_filter.max_range_m"}});
}

TEST_F(ConfigTest, ZeroTurnsOffWhatTheModulesAllowToBeOff) {
  const ScoutConfig c = Load(
      "explore:\n  follower:\n    slow_down_distance_m: 0\n    rotate_in_place_heading_deg: 0\n"
      "slam:\n  local:\n    real_time_correlative_scan_matcher:\n"
      "      linear_search_window_m: 0\n");
  EXPECT_EQ(c.explore.follower.slow_down_distance_m, 0.0);
  EXPECT_EQ(c.explore.follower.rotate_in_place_heading_rad, 0.0);
  EXPECT_EQ(c.slam.local.real_time_correlative_scan_matcher.linear_search_window_m, 0.0);
}

TEST_F(ConfigTest, ValuesOverrideDefaults) {
  const ScoutConfig c =
      LoadConfig(Write("frontier:\n  epsilon_m: 0.2\nsynthetic:\n  lidar:\n    beams: 361\n"));
  EXPECT_DOUBLE_EQ(c.frontier.epsilon_m, 0.2);
  EXPECT_EQ(c.synthetic.lidar.beams, 361);
}

TEST_F(ConfigTest, ErrorsNameTheFileAndKey) {
  std::string e = ErrorOf("frontier:\n  epsilon: 0.1\n");
  EXPECT_NE(e.find("options.yaml"), std::string::npos) << e;
  EXPECT_NE(e.find("frontier.epsilon"), std::string::npos) << e;
  e = ErrorOf("frontier:\n  epsilon_m: fast\n");
  EXPECT_NE(e.find("frontier.epsilon_m"), std::string::npos) << e;
  e = ErrorOf("frontier:\n  epsilon_m: -0.1\n");
  EXPECT_NE(e.find("positive"), std::string::npos) << e;
  e = ErrorOf("synthetic:\n  scans_per_submap: 0\n");
  EXPECT_NE(e.find("synthetic.scans_per_submap"), std::string::npos) << e;
  e = ErrorOf("synthetic:\n  lidar:\n    beam: 3\n");
  EXPECT_NE(e.find("synthetic.lidar.beam"), std::string::npos) << e;
  e = ErrorOf("frontier: [1, 2\n");
  EXPECT_NE(e.find("malformed YAML"), std::string::npos) << e;
  e = ErrorOf("frontier: 3\n");
  EXPECT_NE(e.find("expected a mapping"), std::string::npos) << e;
  try {
    LoadConfig(dir_ / "absent.yaml");
    FAIL();
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("absent.yaml"), std::string::npos);
  }
}

}  // namespace
}  // namespace scout::io
