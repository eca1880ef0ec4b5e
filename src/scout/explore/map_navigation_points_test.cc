#include "scout/explore/map_navigation_points.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "scout/explore/test_maps.h"

namespace scout::explore {
namespace {

using testing::MapBuilder;
using testing::SmallRobot;

// A 1 m wide corridor (cells y 5..14 at 0.1 m) open to unknown space at both
// ends, and above it a room joined by a one-cell gap the robot cannot pass.
MapBuilder CorridorWithSealedRoom() {
  MapBuilder b(80, 20);
  b.Free(10, 5, 69, 14).Wall(10, 4, 69, 4).Wall(10, 15, 69, 15);
  b.Free(40, 16, 49, 19).Wall(39, 16, 39, 19).Wall(50, 16, 50, 19);
  b.Free(45, 15, 45, 15);
  return b;
}

bool IsInput(const std::vector<Eigen::Vector2d>& frontier, const Eigen::Vector2d& p) {
  return std::any_of(frontier.begin(), frontier.end(),
                     [&](const Eigen::Vector2d& f) { return (f - p).norm() < 1e-9; });
}

TEST(MapNavigationPoints, BothCorridorEndsRankedByPathCostAndTheSealedRoomLeftOut) {
  const MapBuilder b = CorridorWithSealedRoom();
  const std::vector<Eigen::Vector2d> frontier = b.FrontierPoints();
  const MapNavigationPoints result =
      NavigationPointsOnMap(b.map(), frontier, b.At(20, 10), {}, SmallRobot(), {});
  EXPECT_FALSE(result.robot_escaped);
  EXPECT_FALSE(result.robot_boxed_in);
  ASSERT_EQ(result.points.size(), 2u);
  // The near end (1 m of path) before the far one (about 5 m): the same
  // unknown area lies beyond both.
  EXPECT_NEAR(result.points[0].position.x(), b.At(10, 0).x(), 1e-9);
  EXPECT_NEAR(result.points[1].position.x(), b.At(69, 0).x(), 1e-9);
  EXPECT_NEAR(result.points[0].cost_m, 1.0, 0.15);
  EXPECT_NEAR(result.points[1].cost_m, 4.9, 0.3);
  EXPECT_GT(result.points[0].revenue, result.points[1].revenue);
  for (const NavigationPoint& p : result.points) {
    EXPECT_TRUE(IsInput(frontier, p.position));  // a frontier cell, never a centroid
    EXPECT_LT(p.position.y(), 1.55);             // nothing in the sealed room
  }
  EXPECT_GE(result.stats.unreachable_components, 1);
}

// The exploration boundary keeps the far end out, as the goal manager does.
TEST(MapNavigationPoints, FrontierOutsideTheBoundaryIsNoGoal) {
  const MapBuilder b = CorridorWithSealedRoom();
  const std::vector<Eigen::Vector2d> frontier = b.FrontierPoints();
  const std::vector<Eigen::Vector2d> boundary = {{0.0, 0.0}, {4.0, 0.0}, {4.0, 2.0}, {0.0, 2.0}};
  const MapNavigationPoints result =
      NavigationPointsOnMap(b.map(), frontier, b.At(20, 10), {}, SmallRobot(), {}, boundary);
  ASSERT_EQ(result.points.size(), 1u);
  EXPECT_NEAR(result.points[0].position.x(), b.At(10, 0).x(), 1e-9);
  EXPECT_GT(result.frontier_points_in_boundary, 0);
  EXPECT_LT(result.frontier_points_in_boundary, static_cast<int>(frontier.size()));
}

TEST(MapNavigationPoints, RobotAgainstAWallLeavesWhereItsDiscFits) {
  const MapBuilder b = CorridorWithSealedRoom();
  // One cell from the wall: inside the inflated band.
  const MapNavigationPoints result =
      NavigationPointsOnMap(b.map(), b.FrontierPoints(), b.At(20, 5), {}, SmallRobot(), {});
  EXPECT_TRUE(result.robot_escaped);
  EXPECT_EQ(result.points.size(), 2u);
}

TEST(MapNavigationPoints, RobotFarFromAnyFreeCellReachesNothing) {
  MapBuilder b(40, 40);
  b.Free(30, 30, 39, 39);
  const MapNavigationPoints result =
      NavigationPointsOnMap(b.map(), b.FrontierPoints(), b.At(2, 2), {}, SmallRobot(), {});
  EXPECT_TRUE(result.robot_boxed_in);
  EXPECT_TRUE(result.points.empty());
}

}  // namespace
}  // namespace scout::explore
