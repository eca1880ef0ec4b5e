#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <utility>

#include "scout/common/atomic_file.h"
#include "scout/common/error.h"
#include "scout/io/config.h"
#include "scout/io/options_file_test_fixture.h"

namespace scout::io {
namespace {

namespace fs = std::filesystem;

using ExploreConfigTest = testing::OptionsFileTest;

TEST_F(ExploreConfigTest, DefaultFileMatchesTheBuiltInDefaults) {
  const ScoutConfig c = LoadConfig(fs::path(SCOUT_SOURCE_DIR) / "config" / "default.yaml");
  const ScoutConfig d;
  EXPECT_DOUBLE_EQ(c.explore.dt_s, d.explore.dt_s);
  EXPECT_DOUBLE_EQ(c.explore.max_sim_time_s, d.explore.max_sim_time_s);
  EXPECT_DOUBLE_EQ(c.explore.no_progress_timeout_s, d.explore.no_progress_timeout_s);
  EXPECT_DOUBLE_EQ(c.explore.min_map_gain_m2, d.explore.min_map_gain_m2);
  EXPECT_DOUBLE_EQ(c.explore.map_update_interval_s, d.explore.map_update_interval_s);
  EXPECT_NEAR(c.explore.initial_turn_rad, d.explore.initial_turn_rad, 1e-12);
  EXPECT_EQ(c.explore.synchronous_slam, d.explore.synchronous_slam);
  EXPECT_DOUBLE_EQ(c.explore.goals.stuck_timeout_s, d.explore.goals.stuck_timeout_s);
  EXPECT_DOUBLE_EQ(c.explore.goals.back_up_distance_m, d.explore.goals.back_up_distance_m);
  EXPECT_DOUBLE_EQ(c.explore.complete_max_reachable_frontier_m,
                   d.explore.complete_max_reachable_frontier_m);
  EXPECT_EQ(c.explore.local_slam.use_online_correlative_scan_matching,
            d.explore.local_slam.use_online_correlative_scan_matching);
  EXPECT_DOUBLE_EQ(c.explore.local_slam.translation_weight,
                   d.explore.local_slam.translation_weight);
  EXPECT_DOUBLE_EQ(c.explore.local_slam.rotation_weight, d.explore.local_slam.rotation_weight);
  EXPECT_DOUBLE_EQ(c.explore.local_slam.likelihood_field_sigma_m,
                   d.explore.local_slam.likelihood_field_sigma_m);
  EXPECT_DOUBLE_EQ(c.explore.frontier_inflation_radius_m, d.explore.frontier_inflation_radius_m);
  EXPECT_EQ(c.explore.boundary, d.explore.boundary);
  EXPECT_DOUBLE_EQ(c.explore.goals.progress_timeout_s, d.explore.goals.progress_timeout_s);
  EXPECT_DOUBLE_EQ(c.explore.goals.max_stand_off_m, d.explore.goals.max_stand_off_m);
  EXPECT_DOUBLE_EQ(c.explore.goals.scan_check_radius_m, d.explore.goals.scan_check_radius_m);
  EXPECT_DOUBLE_EQ(c.explore.goals.stand_off_unknown_margin_m,
                   d.explore.goals.stand_off_unknown_margin_m);
  EXPECT_DOUBLE_EQ(c.explore.goals.close_stuck_passage_radius_m,
                   d.explore.goals.close_stuck_passage_radius_m);
  EXPECT_DOUBLE_EQ(c.explore.goals.last_resort_retrace_m, d.explore.goals.last_resort_retrace_m);
  EXPECT_DOUBLE_EQ(c.explore.goals.last_resort_confined_radius_m,
                   d.explore.goals.last_resort_confined_radius_m);
  EXPECT_DOUBLE_EQ(c.explore.goals.last_resort_confined_s, d.explore.goals.last_resort_confined_s);
  EXPECT_EQ(c.explore.goals.max_last_resorts, d.explore.goals.max_last_resorts);
  EXPECT_DOUBLE_EQ(c.explore.traversability.driven_width_m,
                   d.explore.traversability.driven_width_m);
  EXPECT_DOUBLE_EQ(c.explore.traversability.driven_max_gap_m,
                   d.explore.traversability.driven_max_gap_m);
  EXPECT_DOUBLE_EQ(c.explore.goals.guard.clearance_m, d.explore.goals.guard.clearance_m);
  EXPECT_DOUBLE_EQ(c.explore.goals.guard.horizon_s, d.explore.goals.guard.horizon_s);
  EXPECT_DOUBLE_EQ(c.explore.goals.guard.memory_s, d.explore.goals.guard.memory_s);
  EXPECT_EQ(c.explore.goals.guard.predict_motion, d.explore.goals.guard.predict_motion);
  EXPECT_DOUBLE_EQ(c.explore.goals.guard.stop_turn_radps, d.explore.goals.guard.stop_turn_radps);
  EXPECT_DOUBLE_EQ(c.explore.traversability.narrow_margin_m,
                   d.explore.traversability.narrow_margin_m);
  EXPECT_EQ(c.explore.goals.return_to_start, d.explore.goals.return_to_start);
  EXPECT_EQ(c.explore.goals.failed_goals.max_failures, d.explore.goals.failed_goals.max_failures);
  EXPECT_DOUBLE_EQ(c.explore.traversability.safety_margin_m,
                   d.explore.traversability.safety_margin_m);
  EXPECT_EQ(c.explore.planner.shortcut, d.explore.planner.shortcut);
  EXPECT_NEAR(c.explore.follower.rotate_in_place_heading_rad,
              d.explore.follower.rotate_in_place_heading_rad, 1e-3);
  EXPECT_DOUBLE_EQ(c.explore.policy.navigation.mean_shift.bandwidth_m,
                   d.explore.policy.navigation.mean_shift.bandwidth_m);
  EXPECT_DOUBLE_EQ(c.explore.policy.navigation.info_multiplier,
                   d.explore.policy.navigation.info_multiplier);
  EXPECT_EQ(c.explore.policy.navigation.tour_points, d.explore.policy.navigation.tour_points);
  EXPECT_DOUBLE_EQ(c.explore.policy.navigation.info_visible_range_m,
                   d.explore.policy.navigation.info_visible_range_m);
  EXPECT_DOUBLE_EQ(c.explore.policy.explore_lite.potential_scale,
                   d.explore.policy.explore_lite.potential_scale);
  EXPECT_DOUBLE_EQ(c.robot.robot.radius_m, d.robot.robot.radius_m);
  EXPECT_DOUBLE_EQ(c.robot.robot.max_angular_accel_radps2, d.robot.robot.max_angular_accel_radps2);
  EXPECT_DOUBLE_EQ(c.robot.odometry_rate_hz, d.robot.odometry_rate_hz);
  EXPECT_DOUBLE_EQ(c.robot.start_heading_rad, d.robot.start_heading_rad);
  EXPECT_EQ(c.robot.lidar.beams, d.robot.lidar.beams);
  EXPECT_DOUBLE_EQ(c.robot.odometry.rot_per_trans, d.robot.odometry.rot_per_trans);
}

TEST_F(ExploreConfigTest, ValuesAreReadWithTheirUnits) {
  const ScoutConfig c = Load(
      "explore:\n  max_sim_time_s: 120\n  initial_turn_deg: 90\n  goals:\n    return_to_start: "
      "true\n    scan_check_radius_m: 0.15\n    stand_off_unknown_margin_m: 0.25\n    "
      "scan_check_memory_s: 8\n    last_resort_retrace_m: 3\n    last_resort_confined_radius_m: "
      "0.5\n    last_resort_confined_s: 90\n    max_last_resorts: 0\n    guard:\n     "
      " predict_motion: true\n      "
      "stop_turn_radps: 0\n  follower:\n    "
      "rotate_in_place_heading_deg: "
      "30\nrobot:\n  start_heading_deg: -90\n  lidar:\n    beams: 361\n");
  EXPECT_DOUBLE_EQ(c.explore.max_sim_time_s, 120.0);
  EXPECT_DOUBLE_EQ(Load("explore:\n  local_slam:\n    likelihood_field_sigma_m: 0.05\n")
                       .explore.local_slam.likelihood_field_sigma_m,
                   0.05);
  EXPECT_NEAR(c.explore.initial_turn_rad, std::numbers::pi / 2, 1e-12);
  EXPECT_TRUE(c.explore.goals.return_to_start);
  EXPECT_DOUBLE_EQ(c.explore.goals.scan_check_radius_m, 0.15);
  EXPECT_DOUBLE_EQ(c.explore.goals.stand_off_unknown_margin_m, 0.25);
  EXPECT_DOUBLE_EQ(c.explore.goals.scan_check_memory_s, 8.0);
  EXPECT_DOUBLE_EQ(c.explore.goals.last_resort_retrace_m, 3.0);
  EXPECT_DOUBLE_EQ(c.explore.goals.last_resort_confined_radius_m, 0.5);
  EXPECT_DOUBLE_EQ(c.explore.goals.last_resort_confined_s, 90.0);
  EXPECT_EQ(c.explore.goals.max_last_resorts, 0);
  EXPECT_TRUE(c.explore.goals.guard.predict_motion);
  EXPECT_EQ(c.explore.goals.guard.stop_turn_radps, 0.0);
  EXPECT_NEAR(c.explore.follower.rotate_in_place_heading_rad, std::numbers::pi / 6, 1e-12);
  EXPECT_NEAR(c.robot.start_heading_rad, -std::numbers::pi / 2, 1e-12);
  EXPECT_EQ(c.robot.lidar.beams, 361);
  EXPECT_TRUE(c.explore.boundary.empty());
}

TEST_F(ExploreConfigTest, BoundaryIsAListOfPoints) {
  const ScoutConfig c = Load("explore:\n  boundary: [[0, 0], [4.5, -1], [2, 3.25]]\n");
  ASSERT_EQ(c.explore.boundary.size(), 3u);
  EXPECT_EQ(c.explore.boundary[1], Eigen::Vector2d(4.5, -1.0));
  EXPECT_EQ(c.explore.boundary[2], Eigen::Vector2d(2.0, 3.25));
  // Either orientation.
  EXPECT_EQ(Load("explore:\n  boundary: [[0, 0], [2, 3.25], [4.5, -1]]\n").explore.boundary.size(),
            3u);
  // Too few vertices, a vertex that is not a pair of finite numbers, not a list.
  const std::pair<const char*, const char*> cases[] = {
      {"[[0, 0], [1, 1]]", "'explore.boundary': expected at least three"},
      {"[[0, 0], [1, x], [2, 2]]", "'explore.boundary': item 2"},
      {"[[0, 0, 0], [1, 1], [2, 2]]", "'explore.boundary': item 1"},
      {"[[0, .nan], [1, 1], [2, 2]]", "'explore.boundary': item 1"},
      {"3", "expected a sequence of [x, y] pairs"},
      // A bowtie's second lobe would count as outside; a line holds nothing.
      {"[[2, 5], [5, 7.5], [5, 5], [2, 7.5]]", "the polygon crosses itself"},
      {"[[0, 0], [1, 1], [2, 2]]", "the polygon has no area"},
      {"[[1, 1], [1, 1], [1, 1]]", "the polygon has no area"}};
  for (const auto& [boundary, expected] : cases) {
    const std::string error = ErrorOf(std::string("explore:\n  boundary: ") + boundary + "\n");
    EXPECT_NE(error.find(expected), std::string::npos) << boundary << ": " << error;
  }
}

TEST_F(ExploreConfigTest, ErrorsNameTheKey) {
  EXPECT_NE(ErrorOf("explore:\n  dt_s: -1\n").find("explore.dt_s"), std::string::npos);
  EXPECT_NE(ErrorOf("explore:\n  min_map_gain_m2: -1\n").find("explore.min_map_gain_m2"),
            std::string::npos);
  // The stall rule's old key, on coverage, is gone: named as unknown.
  EXPECT_NE(ErrorOf("explore:\n  min_coverage_gain: 0.001\n").find("explore.min_coverage_gain"),
            std::string::npos);
  EXPECT_NE(ErrorOf("explore:\n  goals:\n    no_such_key: 1\n").find("explore.goals.no_such_key"),
            std::string::npos);
  EXPECT_NE(ErrorOf("robot:\n  lidar:\n    beams: 1\n").find("robot.lidar.beams"),
            std::string::npos);
  // Range checks of the explore module come back as InputError naming the key.
  const std::string field = ErrorOf("explore:\n  local_slam:\n    likelihood_field_sigma_m: -1\n");
  EXPECT_NE(field.find("explore.local_slam.likelihood_field_sigma_m"), std::string::npos) << field;
  const std::string resorts = ErrorOf("explore:\n  goals:\n    max_last_resorts: -1\n");
  EXPECT_NE(resorts.find("explore.goals.max_last_resorts"), std::string::npos) << resorts;
  const std::string resort_m = ErrorOf("explore:\n  goals:\n    last_resort_retrace_m: -2\n");
  EXPECT_NE(resort_m.find("explore.goals.last_resort_retrace_m"), std::string::npos) << resort_m;
  const std::string hysteresis = ErrorOf("explore:\n  goals:\n    max_failures: -1\n");
  EXPECT_NE(hysteresis.find("max_failures"), std::string::npos) << hysteresis;
  const std::string follower = ErrorOf("explore:\n  follower:\n    min_linear_speed_mps: 0.9\n");
  EXPECT_NE(follower.find("explore.follower"), std::string::npos) << follower;
  const std::string predict = ErrorOf("explore:\n  goals:\n    guard:\n      predict_motion: 2\n");
  EXPECT_NE(predict.find("explore.goals.guard.predict_motion"), std::string::npos) << predict;
  const std::string tour = ErrorOf("explore:\n  policy:\n    navigation:\n      tour_points: 1\n");
  EXPECT_NE(tour.find("tour_points': expected 0 (off) or 2 to 12, got 1"), std::string::npos)
      << tour;
  EXPECT_EQ(Load("explore:\n  policy:\n    navigation:\n      tour_points: 5\n")
                .explore.policy.navigation.tour_points,
            5);
  const std::string dropout = ErrorOf("robot:\n  lidar:\n    dropout_probability: 1.5\n");
  EXPECT_NE(dropout.find("robot.lidar.dropout_probability"), std::string::npos) << dropout;
  const std::string fov = ErrorOf("robot:\n  lidar:\n    fov_deg: 400\n");
  EXPECT_NE(fov.find("robot.lidar.fov_deg"), std::string::npos) << fov;
  // Memory for a hundred million beams per scan ran out before the first goal.
  const std::string beams = ErrorOf("robot:\n  lidar:\n    beams: 100000000\n");
  EXPECT_NE(beams.find("'robot.lidar.beams': expected an integer from 2 to 36000"),
            std::string::npos)
      << beams;
  // A step longer than the scan period drops scans (100 s steps drove nowhere).
  const std::string step = ErrorOf("explore:\n  dt_s: 0.5\n");
  EXPECT_NE(step.find("'explore.dt_s': expected at most one scan period"), std::string::npos)
      << step;
  EXPECT_EQ(ErrorOf("explore:\n  dt_s: 0.1\nrobot:\n  odometry_rate_hz: 10\n"), "");
  // Nor can it sample odometry more often than once per step: at 0.1 s steps
  // the default 20 Hz odometry would have been read at 10 Hz, with twice the
  // noise per sample.
  const std::string odometry = ErrorOf("explore:\n  dt_s: 0.1\n");
  EXPECT_NE(odometry.find("'robot.odometry_rate_hz': expected at most one sample per simulation "
                          "step (1 / explore.dt_s = 10 Hz), got 20"),
            std::string::npos)
      << odometry;
  EXPECT_EQ(ErrorOf("explore:\n  dt_s: 0.02\nrobot:\n  odometry_rate_hz: 50\n"), "");
  // 1e-9 s steps never reached a second of simulated time.
  const std::string tiny = ErrorOf("explore:\n  dt_s: 1e-9\n");
  EXPECT_NE(tiny.find("'explore.dt_s': expected a number in [0.001, 1], got 1e-09"),
            std::string::npos)
      << tiny;
}

TEST_F(ExploreConfigTest, LengthsTheLoopWorksThroughHaveAnUpperBound) {
  // Each of these at 1e300 was an internal error (a vector beyond max_size)
  // or a step that never finished, which not even SIGTERM stopped.
  const std::pair<const char*, const char*> cases[] = {
      {"explore:\n  frontier_inflation_radius_m: 1e300\n",
       "'explore.frontier_inflation_radius_m': expected a number in [0, 5], got 1e+300"},
      {"explore:\n  traversability:\n    safety_margin_m: 1e300\n",
       "'explore.traversability.safety_margin_m': expected a number in [0, 5]"},
      {"explore:\n  traversability:\n    narrow_cost_factor: 1e300\n",
       "'explore.traversability.narrow_cost_factor': expected a number in [0, 1000]"},
      {"explore:\n  traversability:\n    goal_snap_radius_m: 100\n",
       "'explore.traversability.goal_snap_radius_m': expected a number in [0, 5]"},
      {"explore:\n  traversability:\n    driven_width_m: 1e5\n",
       "'explore.traversability.driven_width_m'"},
      {"explore:\n  goals:\n    guard:\n      horizon_s: 100\n",
       "'explore.goals.guard.horizon_s': expected a number in [0, 10]"},
      {"explore:\n  policy:\n    navigation:\n      info_radius_m: 1e5\n",
       "'explore.policy.navigation.info_radius_m': expected a number in (0, 10]"},
      {"explore:\n  policy:\n    navigation:\n      info_visible_range_m: 1e300\n",
       "'explore.policy.navigation.info_visible_range_m': expected a number in [0, 20]"}};
  for (const auto& [yaml, expected] : cases) {
    const std::string error = ErrorOf(yaml);
    EXPECT_NE(error.find(expected), std::string::npos) << yaml << ": " << error;
  }
}

}  // namespace
}  // namespace scout::io
