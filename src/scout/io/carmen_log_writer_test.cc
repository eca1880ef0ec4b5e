#include "scout/io/carmen_log_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "scout/common/error.h"
#include "scout/grid/test_temp_directory.h"
#include "scout/io/dataset.h"

namespace scout::io {
namespace {

using grid::TestTempDirectory;

// A 180-degree scan of 'n' beams, both ends included, as the simulated lidar makes.
sensor::LaserScan HalfCircleScan(int n, double time_s) {
  sensor::LaserScan scan;
  scan.time_s = time_s;
  scan.angle_min_rad = static_cast<float>(-std::numbers::pi / 2);
  scan.angle_increment_rad = static_cast<float>(std::numbers::pi / (n - 1));
  scan.range_max_m = 8.f;
  for (int k = 0; k < n; ++k) scan.ranges.push_back(1.0f + 0.01f * static_cast<float>(k));
  return scan;
}

TEST(CarmenLogWriter, WhatItWritesReadsBackWithPosesOdometryTimesAndMissingReturns) {
  TestTempDirectory dir;
  const auto path = dir.path() / "sim.log";
  sensor::LaserScan first = HalfCircleScan(361, 0.1);
  first.ranges[3] = std::numeric_limits<float>::infinity();
  first.ranges[4] = std::numeric_limits<float>::quiet_NaN();
  const sensor::LaserScan second = HalfCircleScan(361, 0.2);
  {
    CarmenLogWriter writer(path);
    writer.AddScan(first, geometry::Rigid2d(1.0, 2.0, 0.5), geometry::Rigid2d(1.1, 2.2, 0.45));
    writer.AddScan(second, geometry::Rigid2d(1.05, 2.0, 0.5), geometry::Rigid2d(1.15, 2.2, 0.46));
    EXPECT_EQ(writer.num_scans(), 2);
    writer.Close();
  }
  const Dataset d = LoadDataset(path);
  ASSERT_EQ(d.scans.size(), 2u);
  ASSERT_EQ(d.scan_poses.size(), 2u);
  ASSERT_EQ(d.scan_odometry.size(), 2u);
  EXPECT_DOUBLE_EQ(d.scans[0].time_s, 0.1);
  EXPECT_DOUBLE_EQ(d.scans[1].time_s, 0.2);
  EXPECT_NEAR(d.scans[0].angle_min_rad, first.angle_min_rad, 1e-6);
  EXPECT_NEAR(d.scans[0].angle_increment_rad, first.angle_increment_rad, 1e-7);
  ASSERT_EQ(d.scans[0].ranges.size(), 361u);
  EXPECT_NEAR(d.scans[0].ranges[100], first.ranges[100], 1e-3);
  EXPECT_TRUE(std::isinf(d.scans[0].ranges[3]));
  EXPECT_TRUE(std::isnan(d.scans[0].ranges[4]));
  EXPECT_NEAR(d.scan_poses[1].x(), 1.05, 1e-6);
  EXPECT_NEAR(d.scan_poses[1].theta(), 0.5, 1e-6);
  EXPECT_NEAR(d.scan_odometry[0].pose.x(), 1.1, 1e-6);
  EXPECT_NEAR(d.scan_odometry[0].pose.y(), 2.2, 1e-6);
  EXPECT_NEAR(d.scan_odometry[1].pose.theta(), 0.46, 1e-6);
  EXPECT_TRUE(d.warnings.empty());
}

// Ranges, poses, times and odometry samples read back bit for bit, so a
// replay feeds SLAM exactly what the loop fed it.
TEST(CarmenLogWriter, NumbersAndOdometrySamplesReadBackExactly) {
  TestTempDirectory dir;
  const auto path = dir.path() / "exact.log";
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> range(0.05, 8.0), coordinate(-50.0, 50.0),
      angle(-3.14, 3.14);
  sensor::LaserScan scan = HalfCircleScan(361, 12.345678901234567);
  for (float& r : scan.ranges) r = static_cast<float>(range(rng));
  const geometry::Rigid2d pose(coordinate(rng), coordinate(rng), angle(rng));
  const geometry::Rigid2d odometry(coordinate(rng), coordinate(rng), angle(rng));
  const std::vector<sensor::Odometry> samples = {
      {12.3, geometry::Rigid2d(coordinate(rng), coordinate(rng), angle(rng))},
      {12.345678901234567, odometry}};
  {
    CarmenLogWriter writer(path);
    for (const sensor::Odometry& o : samples) writer.AddOdometry(o);
    writer.AddScan(scan, pose, odometry);
    EXPECT_EQ(writer.num_odometry(), 2);
    writer.Close();
  }
  const Dataset d = LoadDataset(path);
  ASSERT_EQ(d.scans.size(), 1u);
  EXPECT_EQ(d.scans[0].time_s, scan.time_s);
  EXPECT_EQ(d.scans[0].ranges, scan.ranges);
  EXPECT_EQ(d.scan_poses[0].x(), pose.x());
  EXPECT_EQ(d.scan_poses[0].y(), pose.y());
  EXPECT_EQ(d.scan_poses[0].theta(), pose.theta());
  ASSERT_EQ(d.odometry.size(), 2u);
  for (size_t i = 0; i < samples.size(); ++i) {
    EXPECT_EQ(d.odometry[i].time_s, samples[i].time_s);
    EXPECT_EQ(d.odometry[i].pose.x(), samples[i].pose.x());
    EXPECT_EQ(d.odometry[i].pose.y(), samples[i].pose.y());
    EXPECT_EQ(d.odometry[i].pose.theta(), samples[i].pose.theta());
  }
  EXPECT_TRUE(d.warnings.empty());
}

TEST(CarmenLogWriter, RefusesScansThatAFlaserLineCannotDescribe) {
  TestTempDirectory dir;
  CarmenLogWriter writer(dir.path() / "sim.log");
  sensor::LaserScan wide = HalfCircleScan(361, 0.1);
  wide.angle_min_rad = static_cast<float>(-std::numbers::pi);  // 360 degrees
  wide.angle_increment_rad = static_cast<float>(2 * std::numbers::pi / 360);
  EXPECT_THROW(writer.AddScan(wide, {}, {}), InputError);
  // An even count over 180 degrees with both ends included: FLASER would space it pi / 360.
  EXPECT_THROW(CheckFlaserGeometry(-std::numbers::pi / 2, std::numbers::pi / 359, 360, "lidar"),
               InputError);
  EXPECT_NO_THROW(CheckFlaserGeometry(-std::numbers::pi / 2, std::numbers::pi / 360, 361, "lidar"));
  EXPECT_NO_THROW(CheckFlaserGeometry(-std::numbers::pi / 2, std::numbers::pi / 180, 180, "lidar"));
  EXPECT_EQ(writer.num_scans(), 0);
}

TEST(CarmenLogWriter, NamesAFileItCannotOpen) {
  TestTempDirectory dir;
  try {
    CarmenLogWriter writer(dir.path() / "missing" / "sim.log");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing/sim.log"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace scout::io
