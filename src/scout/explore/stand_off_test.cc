#include "scout/explore/stand_off.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "scout/explore/test_maps.h"

namespace scout::explore {
namespace {

using testing::MapBuilder;

// A free room 40 x 20 cells (0.1 m), unknown beyond x = 30: the frontier is
// the column x = 29. The robot (radius 0.1 m) drives along y = 10.
MapBuilder RoomWithUnknownEnd() {
  MapBuilder b(40, 21);
  b.Free(0, 0, 29, 20);
  return b;
}

TEST(StandOffTest, StopsWhereTheDiscCoversOnlyKnownFreeCells) {
  const MapBuilder b = RoomWithUnknownEnd();
  const PlanningMap map(b.map(), testing::SmallRobot());
  const Eigen::Vector2d goal = b.At(29, 10);  // frontier cell, next to unknown
  EXPECT_FALSE(DiscInKnownFree(map, goal));
  const std::vector<Eigen::Vector2d> path = {b.At(5, 10), goal};
  const std::vector<Eigen::Vector2d> cut = CutAtStandOff(map, path, 0.5, 0.25);
  ASSERT_EQ(cut.size(), 2u);
  EXPECT_EQ(cut.front(), path.front());
  EXPECT_TRUE(DiscInKnownFree(map, cut.back()));
  // The first such point from the goal: the disc (0.1 m) no longer overlaps
  // the unknown column starting at x = 3.0 m.
  EXPECT_NEAR(cut.back().y(), goal.y(), 1e-9);
  EXPECT_NEAR(cut.back().x(), 3.0 - 0.1, 0.051);
  EXPECT_LE(cut.back().x(), 3.0 - 0.1 + 1e-9);
  EXPECT_LE((goal - cut.back()).norm(), 0.5);
}

TEST(StandOffTest, KeepsTheMarginFromUnknownSpaceWhereAPointWithinTheBackOffDoes) {
  const MapBuilder b = RoomWithUnknownEnd();
  const PlanningMap map(b.map(), testing::SmallRobot());
  const Eigen::Vector2d goal = b.At(29, 10);  // x = 2.95 m; unknown from 3.0 m
  const std::vector<Eigen::Vector2d> path = {b.At(5, 10), goal};
  // A 0.1 m disc plus 0.1 m of margin: the stop keeps 0.2 m from x = 3.0 m.
  const std::vector<Eigen::Vector2d> cut = CutAtStandOff(map, path, 0.5, 0.25, 0.1);
  ASSERT_EQ(cut.size(), 2u);
  EXPECT_TRUE(DiscInKnownFree(map, cut.back(), 0.2));
  EXPECT_NEAR(cut.back().y(), goal.y(), 1e-9);
  EXPECT_LE(cut.back().x(), 3.0 - 0.2 + 1e-9);
  EXPECT_GT(cut.back().x(), 3.0 - 0.2 - 0.051);
  // Beyond the back-off (0.15 m of path needed, 0.12 allowed): the stop
  // without the margin.
  EXPECT_EQ(CutAtStandOff(map, path, 0.12, 0.25, 0.1), CutAtStandOff(map, path, 0.12, 0.25));
  EXPECT_NEAR(CutAtStandOff(map, path, 0.12, 0.25, 0.1).back().x(), 2.9, 0.051);
  // A goal that keeps the margin already is driven to.
  const std::vector<Eigen::Vector2d> inside = {b.At(5, 10), b.At(20, 10)};
  EXPECT_EQ(CutAtStandOff(map, inside, 0.5, 0.25, 0.1), inside);
}

TEST(StandOffTest, KeepsPathsThatEndInKnownFreeSpaceOrCannotBackOff) {
  const MapBuilder b = RoomWithUnknownEnd();
  const PlanningMap map(b.map(), testing::SmallRobot());
  const std::vector<Eigen::Vector2d> inside = {b.At(5, 10), b.At(20, 10)};
  EXPECT_EQ(CutAtStandOff(map, inside, 0.5, 0.25), inside);
  const std::vector<Eigen::Vector2d> to_frontier = {b.At(5, 10), b.At(29, 10)};
  // Off, or a back-off too short to leave the unknown's reach.
  EXPECT_EQ(CutAtStandOff(map, to_frontier, 0.0, 0.25), to_frontier);
  EXPECT_EQ(CutAtStandOff(map, to_frontier, 0.05, 0.25), to_frontier);
  // The robot already stands within the back-off: it is not told to stay.
  const std::vector<Eigen::Vector2d> short_path = {b.At(27, 10), b.At(29, 10)};
  EXPECT_EQ(CutAtStandOff(map, short_path, 0.5, 0.25), short_path);
}

TEST(StandOffTest, WalksBackAcrossPathCorners) {
  // A path bending 0.03 m before the frontier cell (29, 10) (unknown from
  // x = 3.0 m): the last leg is too short, the stop lies on the leg before.
  MapBuilder b(40, 40);
  b.Free(0, 0, 29, 39);
  const PlanningMap map(b.map(), testing::SmallRobot());
  const Eigen::Vector2d corner(2.92, 1.05);
  const std::vector<Eigen::Vector2d> path = {b.At(10, 10), corner, b.At(29, 10)};
  const std::vector<Eigen::Vector2d> cut = CutAtStandOff(map, path, 0.5, 0.25);
  EXPECT_TRUE(DiscInKnownFree(map, cut.back()));
  EXPECT_LT(cut.back().x(), corner.x());
  EXPECT_EQ(cut.size(), 2u);
}

// The tiers of the defaults at hand-drawn scale: a 0.1 m disc, 0.2 m of
// safety margin, 0.05 m in narrow passages.
TraversabilityOptions RobotWithNarrowTier() {
  TraversabilityOptions o = testing::SmallRobot();
  o.safety_margin_m = 0.2;
  o.narrow_margin_m = 0.05;
  return o;
}

TEST(StandOffTest, StopsWhereTheFullSafetyMarginIsKept) {
  // A wall block (cells x 27-29 at y = 12) 0.2 m beside the path's last
  // 0.3 m: the goal lies in the narrow band, where a wall the map has
  // 0.1 m off leaves the disc no room. The stop lies in the last cell of the
  // path whose centre keeps 0.3 m from the block's: cell 24 (centre x 2.45,
  // 0.36 m from cell (27, 12)); cell 25 (2.55, 0.28 m) is in the band.
  MapBuilder b = RoomWithUnknownEnd();
  b.Wall(27, 12, 29, 12);
  const PlanningMap map(b.map(), RobotWithNarrowTier());
  const Eigen::Vector2d goal = b.At(29, 10);
  ASSERT_TRUE(map.narrow(map.limits().FlatIndex({29, 10})));
  EXPECT_FALSE(KeepsFullMargin(map, goal));
  const std::vector<Eigen::Vector2d> path = {b.At(5, 10), goal};
  const std::vector<Eigen::Vector2d> cut = CutAtStandOff(map, path, 0.5, 0.25);
  ASSERT_EQ(cut.size(), 2u);
  EXPECT_TRUE(KeepsFullMargin(map, cut.back()));
  EXPECT_TRUE(DiscInKnownFree(map, cut.back()));
  EXPECT_NEAR(cut.back().y(), goal.y(), 1e-9);
  EXPECT_LT(cut.back().x(), 2.5);
  EXPECT_GE(cut.back().x(), 2.4);
  // A goal in known free space but in the band is cut as well.
  const std::vector<Eigen::Vector2d> inside = {b.At(5, 10), b.At(28, 10)};
  EXPECT_LT(CutAtStandOff(map, inside, 0.5, 0.25).back().x(), 2.5);
}

TEST(StandOffTest, InANarrowPassageStopsInKnownFreeSpaceAsBefore) {
  // The wall runs along the whole path: no point within the back-off keeps
  // the full margin, so the stop is the last one whose disc is known free,
  // and a path ending in known free space is kept.
  MapBuilder b = RoomWithUnknownEnd();
  b.Wall(0, 12, 29, 12);
  const PlanningMap map(b.map(), RobotWithNarrowTier());
  const Eigen::Vector2d goal = b.At(29, 10);
  const std::vector<Eigen::Vector2d> path = {b.At(5, 10), goal};
  const std::vector<Eigen::Vector2d> cut = CutAtStandOff(map, path, 0.5, 0.25);
  ASSERT_EQ(cut.size(), 2u);
  EXPECT_FALSE(KeepsFullMargin(map, cut.back()));
  EXPECT_TRUE(DiscInKnownFree(map, cut.back()));
  EXPECT_NEAR(cut.back().x(), 3.0 - 0.1, 0.051);
  const std::vector<Eigen::Vector2d> inside = {b.At(5, 10), b.At(20, 10)};
  EXPECT_EQ(CutAtStandOff(map, inside, 0.5, 0.25), inside);
}

RC_GTEST_PROP(StandOffProperty, TheStopIsOnThePathWithinTheBackOff, ()) {
  // Random known-free rectangle in an unknown map; a straight path from its
  // middle to a random free cell.
  const int w = *rc::gen::inRange(10, 40);
  const int h = *rc::gen::inRange(10, 40);
  MapBuilder b(w + 10, h + 10);
  b.Free(5, 5, w + 4, h + 4);
  const PlanningMap map(b.map(), testing::SmallRobot());
  const Eigen::Vector2d start = b.At(5 + w / 2, 5 + h / 2);
  const Eigen::Vector2d goal = b.At(*rc::gen::inRange(5, w + 5), *rc::gen::inRange(5, h + 5));
  const double back_off = *rc::gen::inRange(0, 10) * 0.1;
  const std::vector<Eigen::Vector2d> path = {start, goal};
  const std::vector<Eigen::Vector2d> cut = CutAtStandOff(map, path, back_off, 0.25);
  RC_ASSERT(!cut.empty());
  RC_ASSERT(cut.front() == start);
  const Eigen::Vector2d stop = cut.back();
  // On the segment, no farther than the back-off from the goal.
  const double along = (stop - start).norm() + (goal - stop).norm();
  RC_ASSERT(std::abs(along - (goal - start).norm()) < 1e-6);
  RC_ASSERT((goal - stop).norm() <= back_off + 1e-9);
  // Either the goal itself, or a stop whose disc is in known free space.
  RC_ASSERT(stop == goal || DiscInKnownFree(map, stop));
}

}  // namespace
}  // namespace scout::explore
