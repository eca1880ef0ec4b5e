#include "scout/explore/scan_memory.h"

#include <gtest/gtest.h>

#include <limits>
#include <numbers>
#include <stdexcept>

namespace scout::explore {
namespace {

TEST(ScanMemoryTest, AWallSeenAheadIsBehindTheRobotAfterItTurnsRound) {
  ScanMemory memory(10.0, 1.0);
  // Facing +x at (2, 1): a return 0.5 m ahead, and one 3 m ahead (too far to keep).
  memory.Add(0.0, geometry::Rigid2d(2.0, 1.0, 0.0), {{0.5, 0.0}, {3.0, 0.0}});
  // Turned round on the spot: the wall is 0.5 m behind.
  const std::vector<Eigen::Vector2d> seen =
      memory.Around(geometry::Rigid2d(2.0, 1.0, std::numbers::pi));
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_NEAR(seen[0].x(), -0.5, 1e-12);
  EXPECT_NEAR(seen[0].y(), 0.0, 1e-12);
  // Farther than the radius from where the robot is now: left out.
  EXPECT_TRUE(memory.Around(geometry::Rigid2d(0.0, 1.0, 0.0)).empty());
}

TEST(ScanMemoryTest, ForgetsScansOlderThanItsMemoryWhileTheRobotMoves) {
  ScanMemory memory(10.0, 1.0);
  memory.Add(0.0, geometry::Rigid2d(0.00, 0.0, 0.0), {{0.5, 0.0}});
  memory.Add(5.0, geometry::Rigid2d(0.01, 0.0, 0.0), {{-0.01, 0.5}});
  EXPECT_EQ(memory.num_scans(), 2);
  EXPECT_EQ(memory.Around(geometry::Rigid2d()).size(), 2u);
  memory.Add(10.5, geometry::Rigid2d(0.02, 0.0, 0.0), {});
  EXPECT_EQ(memory.num_scans(), 2);  // the scan of t = 0 is gone
  const std::vector<Eigen::Vector2d> seen = memory.Around(geometry::Rigid2d());
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_NEAR(seen[0].y(), 0.5, 1e-12);
  ScanMemory none(0.0, 1.0);
  none.Add(0.0, geometry::Rigid2d(), {{0.5, 0.0}});
  EXPECT_EQ(none.num_scans(), 0);
  EXPECT_TRUE(none.Around(geometry::Rigid2d()).empty());
}

TEST(ScanMemoryTest, TimeStandingStillOrTurningOnTheSpotDoesNotAgeIt) {
  ScanMemory memory(10.0, 1.0);
  // A wall seen, then 60 s on the spot (turning, and creeping by less than
  // kStillM per scan): it is still there behind the robot.
  memory.Add(0.0, geometry::Rigid2d(1.0, 0.0, 0.0), {{0.5, 0.0}});
  for (int k = 1; k <= 600; ++k) {
    memory.Add(0.1 * k, geometry::Rigid2d(1.0 + 0.001 * (k % 2), 0.0, 0.01 * k), {});
  }
  EXPECT_EQ(memory.Around(geometry::Rigid2d(1.0, 0.0, std::numbers::pi)).size(), 1u);
  // Moving on, it ages again: 10.5 s of motion drop it.
  for (int k = 1; k <= 105; ++k) {
    memory.Add(60.0 + 0.1 * k, geometry::Rigid2d(1.0 - 0.005 * k, 0.0, 0.0), {});
  }
  EXPECT_TRUE(memory.Around(geometry::Rigid2d(1.0, 0.0, 0.0)).empty());
  // Standing still for long keeps at most kMaxScans scans, the newest.
  ScanMemory still(10.0, 1.0);
  for (int k = 0; k < ScanMemory::kMaxScans + 5; ++k) {
    still.Add(0.1 * k, geometry::Rigid2d(), {{0.5, 0.0001 * k}});
  }
  EXPECT_EQ(still.num_scans(), ScanMemory::kMaxScans);
  const std::vector<Eigen::Vector2d> kept = still.Around(geometry::Rigid2d());
  ASSERT_EQ(kept.size(), static_cast<size_t>(ScanMemory::kMaxScans));
  EXPECT_NEAR(kept.front().y(), 0.0005, 1e-12);  // the first five are gone
}

TEST(ScanMemoryTest, RejectsNegativeOrNonFiniteSettings) {
  EXPECT_THROW(ScanMemory(-1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ScanMemory(1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(ScanMemory(std::numeric_limits<double>::infinity(), 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace scout::explore
