#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "scout/slam/ceres_scan_matcher.h"
#include "scout/slam/point_cloud.h"
#include "scout/slam/real_time_correlative_scan_matcher.h"
#include "scout/slam/test_scene.h"

namespace scout::slam {
namespace {

using geometry::Rigid2d;

double AngleError(const Rigid2d& a, const Rigid2d& b) {
  return std::abs(geometry::NormalizeAngle(a.theta() - b.theta()));
}

TEST(PointCloudTest, TransformAndVoxelFilter) {
  const PointCloud points = {{1.0, 0.0}, {1.01, 0.01}, {2.0, 0.0}, {-0.01, -0.01}};
  const PointCloud moved = TransformPointCloud(points, Rigid2d(1.0, 2.0, std::numbers::pi / 2));
  EXPECT_NEAR(moved[0].x(), 1.0, 1e-12);
  EXPECT_NEAR(moved[0].y(), 3.0, 1e-12);
  const PointCloud filtered = VoxelFilter(points, 0.1);
  ASSERT_EQ(filtered.size(), 3u);  // the first two share a voxel; the first is kept
  EXPECT_EQ(filtered[0], points[0]);
  EXPECT_EQ(filtered[2], points[3]);
  EXPECT_THROW(VoxelFilter(points, 0.0), std::invalid_argument);
}

TEST(PointCloudTest, AdaptiveVoxelFilterKeepsAtLeastMinPointsAndDropsFarOnes) {
  PointCloud points;
  for (int i = 0; i < 1000; ++i) points.push_back({0.01 * i, 0.0});  // a 10 m line
  points.push_back({60.0, 0.0});
  AdaptiveVoxelFilterOptions options;
  const PointCloud filtered = AdaptiveVoxelFilter(points, options);
  EXPECT_GE(filtered.size(), 200u);
  EXPECT_LT(filtered.size(), 400u);  // coarsened as far as allowed, within ~10 %
  for (const Eigen::Vector2d& p : filtered) EXPECT_LE(p.norm(), 50.0);
  options.min_num_points = 2000;  // more than exist: everything in range is kept
  EXPECT_EQ(AdaptiveVoxelFilter(points, options).size(), 1000u);
  options.max_length_m = -1.0;
  EXPECT_THROW(AdaptiveVoxelFilter(points, options), std::invalid_argument);
}

// Matches a scan of the room placed 7 cm, 5 cm and 0.05 rad off its true pose;
// the priors only regularise, the scan alone must pull the pose back.
void ExpectRecoversKnownOffsetOnRoomGrid(CeresScanMatcherOptions options) {
  const grid::ProbabilityGrid grid = testing::RoomGrid();
  const Rigid2d truth(-0.4, 0.3, 0.2);
  const PointCloud points = testing::ScanPoints(testing::Room(), truth);
  const Rigid2d initial(truth.x() + 0.07, truth.y() - 0.05, truth.theta() + 0.05);
  options.translation_weight = 0.1;
  options.rotation_weight = 0.1;
  const CeresScanMatcher matcher(options);
  const auto start = std::chrono::steady_clock::now();
  const Rigid2d result = matcher.Match(initial.translation(), initial, points, grid);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::cout << "Ceres match of " << points.size() << " points: " << ms << " ms\n";
  EXPECT_LT((result.translation() - truth.translation()).norm(), 0.015) << result;
  EXPECT_LT(AngleError(result, truth), 0.005) << result;
}

TEST(CeresScanMatcherTest, RecoversKnownOffsetOnRoomGrid) {
  CeresScanMatcherOptions options;
  options.occupied_space_weight = 20.0;
  ExpectRecoversKnownOffsetOnRoomGrid(options);
}

TEST(CeresScanMatcherTest, RecoversKnownOffsetOnRoomGridFromItsLikelihoodField) {
  CeresScanMatcherOptions options;
  options.likelihood_field.sigma_m = 0.06;
  ExpectRecoversKnownOffsetOnRoomGrid(options);
}

TEST(CeresScanMatcherTest, DefaultPriorsHoldAPoseTheScanAgreesWith) {
  const grid::ProbabilityGrid grid = testing::RoomGrid();
  const Rigid2d truth(0.3, -0.2, -0.4);
  const PointCloud points = testing::ScanPoints(testing::Room(), truth);
  const CeresScanMatcher matcher(CeresScanMatcherOptions{});
  const Rigid2d result = matcher.Match(truth.translation(), truth, points, grid);
  EXPECT_LT((result.translation() - truth.translation()).norm(), 0.01) << result;
  EXPECT_LT(AngleError(result, truth), 0.005) << result;
  // An empty scan leaves the estimate alone.
  const Rigid2d unchanged = matcher.Match({1.0, 1.0}, truth, {}, grid);
  EXPECT_EQ(unchanged.translation(), truth.translation());
}

// A robot driving down a corridor sees its walls 8 m ahead, beyond what the
// map holds. Scoring unmapped cells as the minimum probability (as
// Cartographer does) pulls each scan back into mapped space, and the pose
// lags behind a perfect odometry; at 0.5 the pull is weaker.
double CorridorLagM(double unknown_probability, double translation_weight) {
  const std::vector<testing::Segment> walls = {{{-10.0, -1.02}, {40.0, -1.02}},
                                               {{-10.0, 1.03}, {40.0, 1.03}}};
  grid::ProbabilityGrid grid(grid::MapLimits(0.05, {-2.0, -1.5}, 300, 60));
  const grid::RangeDataInserter inserter({});
  CeresScanMatcherOptions options;
  options.translation_weight = translation_weight;
  options.rotation_weight = 1.0;
  options.unknown_probability = unknown_probability;
  const CeresScanMatcher matcher(options);
  Rigid2d estimate;
  for (int i = 0; i < 60; ++i) {
    const Rigid2d truth(0.05 * i, 0.0, 0.0);
    // A forward-looking 180 degree lidar, like the simulated robot's.
    PointCloud points;
    for (const Eigen::Vector2d& p :
         sensor::ToRangeData(testing::CastScan(walls, truth, 0.0, 360, 8.f), {}).returns) {
      if (p.x() >= 0.0) points.push_back(p);
    }
    if (i > 0) {
      // Perfect odometry: the prediction moves exactly as the robot did.
      const Rigid2d prediction = estimate * Rigid2d(0.05, 0.0, 0.0);
      estimate = matcher.Match(prediction.translation(), prediction, points, grid);
    }
    inserter.Insert(estimate.translation(), TransformPointCloud(points, estimate), {}, &grid);
  }
  return 0.05 * 59 - estimate.x();
}

TEST(CeresScanMatcherTest, UnknownAtHalfDoesNotPullScansBackIntoMappedSpace) {
  const double lag_minimum_m = CorridorLagM(0.1, 5.0);
  const double lag_half_m = CorridorLagM(0.5, 5.0);
  // Measured: 0.148 m and 0.060 m after 3 m (translation weight 5, the
  // explore default; at 10: 0.028 and 0.012 m).
  EXPECT_GT(lag_minimum_m, 0.1);
  EXPECT_LT(std::abs(lag_half_m), 0.5 * lag_minimum_m);
}

// A scan of three returns, 0.1 rad off a prior it disagrees with: divided by
// sqrt(3) alone its three residuals weigh as much as a full scan's and turn
// the pose most of the way; with full_weight_num_points the prior holds it.
// Scans with at least that many points match exactly as before.
TEST(CeresScanMatcherTest, FewReturnsPullWithTheirShareOfTheFullWeight) {
  const grid::ProbabilityGrid grid = testing::RoomGrid();
  const Rigid2d truth(0.3, -0.2, -0.4);
  const PointCloud all_points = testing::ScanPoints(testing::Room(), truth);
  ASSERT_GE(all_points.size(), 50u);
  const PointCloud few = {all_points[all_points.size() / 4], all_points[all_points.size() / 2],
                          all_points[3 * all_points.size() / 4]};
  const Rigid2d prior(truth.x(), truth.y(), truth.theta() + 0.1);
  CeresScanMatcherOptions options;
  options.translation_weight = 5.0;
  options.rotation_weight = 1.0;
  const Rigid2d sqrt_n = CeresScanMatcher(options).Match(prior.translation(), prior, few, grid);
  options.full_weight_num_points = 50;
  const Rigid2d shared = CeresScanMatcher(options).Match(prior.translation(), prior, few, grid);
  EXPECT_GT(AngleError(sqrt_n, prior), 0.05) << sqrt_n;
  EXPECT_LT(AngleError(shared, prior), 0.02) << shared;

  const Rigid2d full_prior(truth.x() + 0.03, truth.y(), truth.theta() + 0.03);
  options.full_weight_num_points = static_cast<int>(all_points.size());
  const Rigid2d full_shared =
      CeresScanMatcher(options).Match(full_prior.translation(), full_prior, all_points, grid);
  options.full_weight_num_points = 0;
  const Rigid2d full_sqrt_n =
      CeresScanMatcher(options).Match(full_prior.translation(), full_prior, all_points, grid);
  EXPECT_EQ(full_shared.translation(), full_sqrt_n.translation());
  EXPECT_EQ(full_shared.theta(), full_sqrt_n.theta());
}

TEST(CeresScanMatcherTest, RejectsInvalidOptions) {
  CeresScanMatcherOptions options;
  options.max_num_iterations = 0;
  EXPECT_THROW(CeresScanMatcher{options}, std::invalid_argument);
  options = {};
  options.occupied_space_weight = std::nan("");
  EXPECT_THROW(CeresScanMatcher{options}, std::invalid_argument);
  options = {};
  options.full_weight_num_points = -1;
  EXPECT_THROW(CeresScanMatcher{options}, std::invalid_argument);
  options = {};
  options.likelihood_field.sigma_m = -0.1;
  EXPECT_THROW(CeresScanMatcher{options}, std::invalid_argument);
  options.likelihood_field.sigma_m = std::nan("");
  EXPECT_THROW(CeresScanMatcher{options}, std::invalid_argument);
  options = {};
  options.likelihood_field.occupied_probability = 0.95;
  EXPECT_THROW(CeresScanMatcher{options}, std::invalid_argument);
}

TEST(RealTimeCorrelativeScanMatcherTest, RecoversOffsetWithinWindow) {
  const grid::ProbabilityGrid grid = testing::RoomGrid();
  const Rigid2d truth(-0.4, 0.3, 0.2);
  const PointCloud points = testing::ScanPoints(testing::Room(), truth);
  const Rigid2d initial(truth.x() + 0.08, truth.y() - 0.07, truth.theta() - 0.2);
  const RealTimeCorrelativeScanMatcher matcher(RealTimeCorrelativeScanMatcherOptions{});
  const auto start = std::chrono::steady_clock::now();
  const ScanMatchResult result = matcher.Match(initial, points, grid);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::cout << "Real-time correlative match of " << points.size() << " points: " << ms << " ms\n";
  // Within one cell and about one angular step of the truth.
  EXPECT_LT((result.pose.translation() - truth.translation()).norm(), 0.05) << result.pose;
  EXPECT_LT(AngleError(result.pose, truth), 0.01) << result.pose;
  EXPECT_GT(result.score, 0.6);
  // The refined pose must score better than the initial estimate.
  const ScanMatchResult at_initial =
      RealTimeCorrelativeScanMatcher({.linear_search_window_m = 0.0,
                                      .angular_search_window_rad = 0.0,
                                      .translation_delta_cost_weight = 0.1,
                                      .rotation_delta_cost_weight = 0.1,
                                      .unknown_probability = 0.5,
                                      .likelihood_field = {}})
          .Match(initial, points, grid);
  EXPECT_EQ(at_initial.pose.translation(), initial.translation());
  EXPECT_LT(at_initial.score, result.score - 0.1);
}

TEST(RealTimeCorrelativeScanMatcherTest, RecoversOffsetWithinWindowOnTheLikelihoodField) {
  const grid::ProbabilityGrid grid = testing::RoomGrid();
  const Rigid2d truth(-0.4, 0.3, 0.2);
  const PointCloud points = testing::ScanPoints(testing::Room(), truth);
  const Rigid2d initial(truth.x() + 0.08, truth.y() - 0.07, truth.theta() - 0.2);
  RealTimeCorrelativeScanMatcherOptions options;
  options.likelihood_field.sigma_m = 0.06;
  const ScanMatchResult result =
      RealTimeCorrelativeScanMatcher(options).Match(initial, points, grid);
  EXPECT_LT((result.pose.translation() - truth.translation()).norm(), 0.05) << result.pose;
  EXPECT_LT(AngleError(result.pose, truth), 0.01) << result.pose;
  // Most points lie on a wall cell, where the field is 1.
  EXPECT_GT(result.score, 0.7);
  options.linear_search_window_m = 0.0;
  options.angular_search_window_rad = 0.0;
  const ScanMatchResult at_initial =
      RealTimeCorrelativeScanMatcher(options).Match(initial, points, grid);
  EXPECT_EQ(at_initial.pose.translation(), initial.translation());
  EXPECT_LT(at_initial.score, result.score - 0.3);
}

TEST(RealTimeCorrelativeScanMatcherTest, ThenCeresRefinesBelowACell) {
  const grid::ProbabilityGrid grid = testing::RoomGrid();
  const Rigid2d truth(0.7, -0.9, 2.5);
  const PointCloud points = testing::ScanPoints(testing::Room(), truth);
  const Rigid2d initial(truth.x() - 0.09, truth.y() + 0.06, truth.theta() + 0.25);
  const ScanMatchResult coarse =
      RealTimeCorrelativeScanMatcher(RealTimeCorrelativeScanMatcherOptions{})
          .Match(initial, points, grid);
  const Rigid2d fine = CeresScanMatcher(CeresScanMatcherOptions{})
                           .Match(coarse.pose.translation(), coarse.pose, points, grid);
  EXPECT_LT((fine.translation() - truth.translation()).norm(), 0.03)
      << fine << " from " << coarse.pose;
  EXPECT_LT(AngleError(fine, truth), 0.01) << fine;
}

TEST(RealTimeCorrelativeScanMatcherTest, APickOnTheAngularEdgeCanFallBackToTheInitialEstimate) {
  const grid::ProbabilityGrid grid = testing::RoomGrid();
  const Rigid2d truth(-0.4, 0.3, 0.2);
  const PointCloud points = testing::ScanPoints(testing::Room(), truth);
  RealTimeCorrelativeScanMatcherOptions options;  // a window of 20 degrees
  options.initial_estimate_at_angular_edge = false;
  // Turned 22 degrees off the truth: the best candidate in the window is
  // the one turned furthest toward it, on the window's edge.
  const Rigid2d beyond(truth.x(), truth.y(), truth.theta() - 22.0 * std::numbers::pi / 180.0);
  bool edge = false;
  const ScanMatchResult on_edge =
      RealTimeCorrelativeScanMatcher(options).Match(beyond, points, grid, &edge);
  EXPECT_NEAR(on_edge.pose.theta() - beyond.theta(), options.angular_search_window_rad, 0.01);
  EXPECT_TRUE(edge);
  options.initial_estimate_at_angular_edge = true;
  edge = false;
  const ScanMatchResult fallen_back =
      RealTimeCorrelativeScanMatcher(options).Match(beyond, points, grid, &edge);
  EXPECT_TRUE(edge);
  EXPECT_EQ(fallen_back.pose.translation(), beyond.translation());
  EXPECT_EQ(fallen_back.pose.theta(), beyond.theta());
  EXPECT_GT(fallen_back.score, 0.0);  // the initial estimate's own score
  EXPECT_LT(fallen_back.score, on_edge.score);
  // Within the window the option changes nothing.
  const Rigid2d within(truth.x() + 0.08, truth.y() - 0.07, truth.theta() - 0.2);
  options.initial_estimate_at_angular_edge = false;
  const ScanMatchResult plain = RealTimeCorrelativeScanMatcher(options).Match(within, points, grid);
  options.initial_estimate_at_angular_edge = true;
  const ScanMatchResult guarded =
      RealTimeCorrelativeScanMatcher(options).Match(within, points, grid, &edge);
  EXPECT_FALSE(edge);
  EXPECT_LT(AngleError(guarded.pose, truth), 0.01) << guarded.pose;
  EXPECT_EQ(guarded.pose.translation(), plain.pose.translation());
  EXPECT_EQ(guarded.pose.theta(), plain.pose.theta());
}

TEST(RealTimeCorrelativeScanMatcherTest, EmptyScanAndInvalidOptions) {
  const grid::ProbabilityGrid grid = testing::RoomGrid();
  const Rigid2d initial(0.1, 0.2, 0.3);
  const ScanMatchResult result =
      RealTimeCorrelativeScanMatcher(RealTimeCorrelativeScanMatcherOptions{})
          .Match(initial, {}, grid);
  EXPECT_EQ(result.pose.translation(), initial.translation());
  EXPECT_EQ(result.score, 0.0);
  RealTimeCorrelativeScanMatcherOptions options;
  options.angular_search_window_rad = 4.0;
  EXPECT_THROW(RealTimeCorrelativeScanMatcher{options}, std::invalid_argument);
  options = {};
  options.likelihood_field.sigma_m = -1.0;
  EXPECT_THROW(RealTimeCorrelativeScanMatcher{options}, std::invalid_argument);
  options = {};
  options.likelihood_field.occupied_probability = 0.05;
  EXPECT_THROW(RealTimeCorrelativeScanMatcher{options}, std::invalid_argument);
}

}  // namespace
}  // namespace scout::slam
