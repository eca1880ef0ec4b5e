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

TEST(ScanMemoryTest, ForgetsScansOlderThanItsMemory) {
  ScanMemory memory(10.0, 1.0);
  memory.Add(0.0, geometry::Rigid2d(), {{0.5, 0.0}});
  memory.Add(5.0, geometry::Rigid2d(), {{0.0, 0.5}});
  EXPECT_EQ(memory.num_scans(), 2);
  EXPECT_EQ(memory.Around(geometry::Rigid2d()).size(), 2u);
  memory.Add(10.5, geometry::Rigid2d(), {});
  EXPECT_EQ(memory.num_scans(), 2);  // the scan of t = 0 is gone
  const std::vector<Eigen::Vector2d> seen = memory.Around(geometry::Rigid2d());
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_NEAR(seen[0].y(), 0.5, 1e-12);
  ScanMemory none(0.0, 1.0);
  none.Add(0.0, geometry::Rigid2d(), {{0.5, 0.0}});
  EXPECT_EQ(none.num_scans(), 0);
  EXPECT_TRUE(none.Around(geometry::Rigid2d()).empty());
}

TEST(ScanMemoryTest, RejectsNegativeOrNonFiniteSettings) {
  EXPECT_THROW(ScanMemory(-1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ScanMemory(1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(ScanMemory(std::numeric_limits<double>::infinity(), 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace scout::explore
