#include "scout/io/odometry_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <stdexcept>

namespace scout::io {
namespace {

// 'steps' moves of 'step_m' straight ahead along x, 10 Hz.
std::vector<sensor::Odometry> StraightLine(int steps, double step_m) {
  std::vector<sensor::Odometry> odometry;
  for (int i = 0; i <= steps; ++i)
    odometry.push_back({0.1 * i, geometry::Rigid2d(step_m * i, 0, 0)});
  return odometry;
}

// A square loop with turns in place, so every part of the model is exercised.
std::vector<sensor::Odometry> SquareLoop() {
  std::vector<sensor::Odometry> odometry;
  geometry::Rigid2d pose(1.0, -2.0, 0.3);
  double time = 0.0;
  for (int side = 0; side < 4; ++side) {
    for (int i = 0; i < 20; ++i) {
      odometry.push_back({time += 0.1, pose});
      pose = pose * geometry::Rigid2d(0.1, 0, 0);
    }
    for (int i = 0; i < 10; ++i) {
      odometry.push_back({time += 0.1, pose});
      pose = pose * geometry::Rigid2d(0, 0, std::numbers::pi / 20);
    }
  }
  return odometry;
}

bool SamePoses(const std::vector<sensor::Odometry>& a, const std::vector<sensor::Odometry>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].time_s != b[i].time_s || a[i].pose.x() != b[i].pose.x() ||
        a[i].pose.y() != b[i].pose.y() || a[i].pose.theta() != b[i].pose.theta()) {
      return false;
    }
  }
  return true;
}

struct EndErrors {
  double heading_sd_rad, along_sd_m, cross_sd_m;
};

// Error statistics of the end pose of 'odometry' over many seeds.
EndErrors MeasureEndErrors(const std::vector<sensor::Odometry>& odometry, double scale) {
  constexpr int kRuns = 2000;
  double heading = 0.0, along = 0.0, cross = 0.0;
  const geometry::Rigid2d& truth = odometry.back().pose;
  for (int seed = 0; seed < kRuns; ++seed) {
    const geometry::Rigid2d error =
        truth.inverse() * AddOdometryNoise(odometry, scale, seed).back().pose;
    heading += error.theta() * error.theta();
    along += error.x() * error.x();
    cross += error.y() * error.y();
  }
  return {std::sqrt(heading / kRuns), std::sqrt(along / kRuns), std::sqrt(cross / kRuns)};
}

TEST(OdometryNoise, ScaleZeroReturnsTheInputUnchanged) {
  const std::vector<sensor::Odometry> odometry = SquareLoop();
  EXPECT_TRUE(SamePoses(AddOdometryNoise(odometry, 0.0, 7), odometry));
  EXPECT_TRUE(AddOdometryNoise({}, 1.0, 7).empty());
}

TEST(OdometryNoise, SameSeedSameOutputOtherSeedOtherOutput) {
  const std::vector<sensor::Odometry> odometry = SquareLoop();
  const std::vector<sensor::Odometry> a = AddOdometryNoise(odometry, 1.0, 42);
  EXPECT_TRUE(SamePoses(a, AddOdometryNoise(odometry, 1.0, 42)));
  EXPECT_FALSE(SamePoses(a, AddOdometryNoise(odometry, 1.0, 43)));
  EXPECT_FALSE(SamePoses(a, odometry));
  // The first pose and all times are kept.
  EXPECT_TRUE(SamePoses({a.front()}, {odometry.front()}));
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].time_s, odometry[i].time_s);
}

TEST(OdometryNoise, DriftOverTenMetresMatchesTheDocumentedModel) {
  const EndErrors errors = MeasureEndErrors(StraightLine(100, 0.1), 1.0);
  std::cout << "10 m straight, scale 1: heading sd " << errors.heading_sd_rad << " rad, along "
            << errors.along_sd_m << " m, cross " << errors.cross_sd_m << " m\n";
  // Documented in odometry_noise.h; 2000 runs give a few percent sampling error.
  EXPECT_NEAR(errors.heading_sd_rad, 0.01 * std::sqrt(10.0), 0.003);
  EXPECT_NEAR(errors.along_sd_m, 0.05 * std::sqrt(10.0), 0.015);
  EXPECT_NEAR(errors.cross_sd_m, 0.18, 0.02);
  // Random-walk variances: the drift does not depend on the odometry rate.
  const EndErrors coarse = MeasureEndErrors(StraightLine(10, 1.0), 1.0);
  EXPECT_NEAR(coarse.heading_sd_rad, errors.heading_sd_rad, 0.003);
  EXPECT_NEAR(coarse.along_sd_m, errors.along_sd_m, 0.015);
}

TEST(OdometryNoise, DriftGrowsWithScale) {
  const std::vector<sensor::Odometry> odometry = StraightLine(100, 0.1);
  const EndErrors small = MeasureEndErrors(odometry, 0.5);
  const EndErrors large = MeasureEndErrors(odometry, 2.0);
  EXPECT_NEAR(large.heading_sd_rad / small.heading_sd_rad, 4.0, 0.4);
  EXPECT_NEAR(large.along_sd_m / small.along_sd_m, 4.0, 0.4);
}

TEST(OdometryNoise, TurningInPlaceDriftsInHeadingOnly) {
  std::vector<sensor::Odometry> odometry;
  for (int i = 0; i <= 40; ++i) {
    odometry.push_back({0.1 * i, geometry::Rigid2d(0, 0, 2 * std::numbers::pi * i / 40)});
  }
  const EndErrors errors = MeasureEndErrors(odometry, 1.0);
  EXPECT_NEAR(errors.heading_sd_rad, 0.05 * std::sqrt(2 * std::numbers::pi), 0.01);
  EXPECT_LT(errors.along_sd_m, 0.05);
}

TEST(OdometryNoise, RejectsNegativeScale) {
  EXPECT_THROW(AddOdometryNoise(SquareLoop(), -1.0, 1), std::invalid_argument);
  EXPECT_THROW(AddOdometryNoise(SquareLoop(), NAN, 1), std::invalid_argument);
}

}  // namespace
}  // namespace scout::io
