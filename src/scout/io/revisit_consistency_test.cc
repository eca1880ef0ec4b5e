#include "scout/io/revisit_consistency.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "scout/io/room_scan_test_util.h"
#include "scout/io/scan_consistency.h"

namespace scout::io {
namespace {

using geometry::Rigid2d;
using scout::io::testing::RoomScan;

// Two laps of a circle of radius 'radius_m' about (cx, cy), one scan a second,
// 'per_lap' scans a lap, facing along the circle.
struct Laps {
  std::vector<Rigid2d> poses;
  std::vector<double> times_s;
};

Laps TwoLaps(double cx, double cy, double radius_m, int per_lap) {
  Laps laps;
  for (int i = 0; i < 2 * per_lap; ++i) {
    const double a = 2.0 * M_PI * i / per_lap;
    laps.poses.emplace_back(cx + radius_m * std::cos(a), cy + radius_m * std::sin(a),
                            a + M_PI / 2.0);
    laps.times_s.push_back(i);
  }
  return laps;
}

TEST(RevisitConsistencyTest, TheSecondLapRevisitsTheNearestScansOfTheFirst) {
  // 40 scans a lap, 9 degrees apart on a 3 m circle: neighbours 0.47 m and
  // 0.94 m apart, the next 1.41 m.
  const Laps laps = TwoLaps(0.0, 0.0, 3.0, 40);
  const std::vector<std::vector<int>> revisits = FindRevisits(laps.poses, laps.times_s);
  // Nothing is 30 s older than the first lap's scans near its start.
  for (int i = 0; i < 30; ++i) EXPECT_TRUE(revisits[i].empty()) << i;
  // Scan 45 stands where scan 5 stood; 4 and 6, 3 and 7 are the neighbours.
  ASSERT_EQ(revisits[45].size(), 5u);
  EXPECT_EQ(revisits[45].front(), 5);
  for (const int j : revisits[45]) EXPECT_TRUE(j >= 3 && j <= 7) << j;
  // At most max_earlier_scans, nearest first: the scan on the same spot.
  EXPECT_EQ(FindRevisits(laps.poses, laps.times_s, {.max_earlier_scans = 1})[45],
            std::vector<int>{5});
  // Headings 18 degrees apart fail a 10 degree limit.
  EXPECT_EQ(FindRevisits(laps.poses, laps.times_s, {.max_turn_deg = 10.0})[45].size(), 3u);
  // Scan 5 is only 40 s older than scan 45.
  EXPECT_TRUE(FindRevisits(laps.poses, laps.times_s, {.min_separation_s = 50.0})[45].empty());
}

TEST(RevisitConsistencyTest, MergeKeepsEachEarlierScanOnce) {
  const std::vector<std::vector<int>> merged = MergeRevisits({{}, {3, 1}, {}}, {{}, {1, 2}, {0}});
  EXPECT_EQ(merged, (std::vector<std::vector<int>>{{}, {1, 2, 3}, {0}}));
}

TEST(RevisitConsistencyTest, ALoopClosedOffShowsWhereTheLocalMeasureDoesNot) {
  // Two laps of a 1 m circle in the room; scans from the true poses.
  const Laps truth = TwoLaps(-2.0, 0.0, 1.0, 40);
  std::vector<std::vector<Eigen::Vector2d>> points;
  for (const Rigid2d& pose : truth.poses) points.push_back(RoomScan(pose));
  const std::vector<std::vector<int>> revisits = FindRevisits(truth.poses, truth.times_s);
  const RevisitConsistency exact = MeasureRevisitConsistency(points, truth.poses, revisits);
  // Scans 35-79: from scan 35 on, the first lap's start is 30 s older and
  // within 45 degrees of heading (five scans of 9 degrees).
  EXPECT_EQ(exact.scans, 45);
  EXPECT_LT(exact.mean_distance_m, 0.02);
  EXPECT_GT(exact.paired_fraction, 0.95);

  // The estimate puts the second lap 0.1 m east of the first: the loop was
  // closed off. Within each lap the poses are exact.
  std::vector<Rigid2d> shifted = truth.poses;
  for (size_t i = 40; i < shifted.size(); ++i) {
    shifted[i] = Rigid2d(shifted[i].translation() + Eigen::Vector2d(0.1, 0.0), shifted[i].theta());
  }
  const double local = MeasureScanConsistency(points, shifted).mean_distance_m;
  const double local_exact = MeasureScanConsistency(points, truth.poses).mean_distance_m;
  EXPECT_LT(local, local_exact + 0.01);
  const RevisitConsistency off = MeasureRevisitConsistency(points, shifted, revisits);
  EXPECT_GT(off.mean_distance_m, exact.mean_distance_m + 0.03);

  // A metre off, the walls across the shift no longer pair at all.
  for (size_t i = 40; i < shifted.size(); ++i) {
    shifted[i] =
        Rigid2d(truth.poses[i].translation() + Eigen::Vector2d(1.0, 0.0), truth.poses[i].theta());
  }
  const RevisitConsistency far = MeasureRevisitConsistency(points, shifted, revisits);
  EXPECT_LT(far.paired_fraction, exact.paired_fraction - 0.2);
}

TEST(RevisitConsistencyTest, NoRevisitsMeasureNothing) {
  const Laps laps = TwoLaps(0.0, 0.0, 1.0, 10);
  const std::vector<std::vector<Eigen::Vector2d>> points(laps.poses.size());
  const RevisitConsistency none = MeasureRevisitConsistency(
      points, laps.poses, std::vector<std::vector<int>>(laps.poses.size()));
  EXPECT_EQ(none.scans, 0);
  EXPECT_TRUE(std::isnan(none.mean_distance_m));
  EXPECT_TRUE(std::isnan(none.paired_fraction));
}

TEST(RevisitConsistencyTest, RejectsMismatchedSizesBadIndicesAndBadOptions) {
  const std::vector<Rigid2d> poses(2);
  EXPECT_THROW(FindRevisits(poses, {0.0}), std::invalid_argument);
  EXPECT_THROW(FindRevisits(poses, {0.0, 1.0}, {.max_distance_m = 0.0}), std::invalid_argument);
  EXPECT_THROW(FindRevisits(poses, {0.0, 1.0}, {.max_earlier_scans = 0}), std::invalid_argument);
  EXPECT_THROW(FindRevisits(poses, {0.0, 1.0}, {.min_separation_s = -1.0}), std::invalid_argument);
  EXPECT_THROW(MergeRevisits({{}}, {}), std::invalid_argument);
  const std::vector<std::vector<Eigen::Vector2d>> points(2);
  EXPECT_THROW(MeasureRevisitConsistency(points, poses, {{}, {5}}), std::invalid_argument);
  EXPECT_THROW(MeasureRevisitConsistency(points, poses, {{}}), std::invalid_argument);
  EXPECT_THROW(MeasureRevisitConsistency(points, poses, {{}, {}}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace scout::io
