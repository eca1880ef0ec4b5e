#include "scout/io/scan_consistency.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "scout/io/room_scan_test_util.h"

namespace scout::io {
namespace {

using geometry::Rigid2d;
using scout::io::testing::RoomScan;

struct Lap {
  std::vector<std::vector<Eigen::Vector2d>> points;
  std::vector<Rigid2d> poses;
};

Lap RoomLap() {
  Lap lap;
  for (int i = 0; i < 40; ++i) {
    const Rigid2d pose(-3.0 + 0.1 * i, -1.5 + 0.02 * i, 0.05 * i);
    lap.points.push_back(RoomScan(pose));
    lap.poses.push_back(pose);
  }
  return lap;
}

TEST(ScanConsistencyTest, ExactPosesAgreeAndHeadingNoiseShowsUp) {
  const Lap lap = RoomLap();
  const ScanConsistency exact = MeasureScanConsistency(lap.points, lap.poses);
  EXPECT_EQ(exact.scans, 30);
  // Only the spacing of the returns along the walls remains (about a
  // centimetre at 1 degree and a few metres).
  EXPECT_LT(exact.mean_distance_m, 0.02);
  std::mt19937 random(5);
  std::normal_distribution<double> heading(0.0, 0.5 * M_PI / 180.0);
  std::vector<Rigid2d> noisy = lap.poses;
  for (Rigid2d& pose : noisy) pose = Rigid2d(pose.translation(), pose.theta() + heading(random));
  const ScanConsistency smeared = MeasureScanConsistency(lap.points, noisy);
  EXPECT_GT(smeared.mean_distance_m, exact.mean_distance_m + 0.005);
}

TEST(ScanConsistencyTest, AWallSeenFiveCentimetresOffMeasuresFiveCentimetres) {
  // Two scans of one straight wall, dense along it; the second pose is off
  // by 5 cm across the wall.
  std::vector<Eigen::Vector2d> wall;
  for (int k = -200; k <= 200; ++k) wall.emplace_back(2.0, 0.005 * k);
  const ScanConsistency c = MeasureScanConsistency(
      {wall, wall}, {Rigid2d(0.0, 0.0, 0.0), Rigid2d(0.05, 0.0, 0.0)}, {.previous_scans = 1});
  EXPECT_EQ(c.scans, 1);
  EXPECT_NEAR(c.mean_distance_m, 0.05, 1e-9);
  // Beyond max_distance_m nothing pairs: a wall the earlier scans never saw.
  const ScanConsistency apart = MeasureScanConsistency(
      {wall, wall}, {Rigid2d(0.0, 0.0, 0.0), Rigid2d(0.5, 0.0, 0.0)}, {.previous_scans = 1});
  EXPECT_EQ(apart.scans, 0);
  EXPECT_TRUE(std::isnan(apart.mean_distance_m));
}

TEST(ScanConsistencyTest, RejectsMismatchedSizesAndBadOptions) {
  EXPECT_THROW(MeasureScanConsistency({{}}, {}), std::invalid_argument);
  EXPECT_THROW(MeasureScanConsistency({}, {}, {.previous_scans = 0}), std::invalid_argument);
  EXPECT_THROW(MeasureScanConsistency({}, {}, {.previous_scans = 1, .max_distance_m = 0.0}),
               std::invalid_argument);
  EXPECT_EQ(MeasureScanConsistency({}, {}).scans, 0);
}

}  // namespace
}  // namespace scout::io
