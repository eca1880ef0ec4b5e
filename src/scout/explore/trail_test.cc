#include "scout/explore/trail.h"

#include <gtest/gtest.h>

#include <cmath>

namespace scout::explore {
namespace {

TEST(TrailTest, KeepsPointsAStepApartAndAtMostTheLengthAsked) {
  Trail trail;
  // 1 cm steps along x for 3 m: every second one is recorded.
  for (int k = 0; k <= 300; ++k) trail.Record({0.01 * k, 0.0}, 1.0);
  ASSERT_GE(trail.points().size(), 2u);
  for (size_t i = 1; i < trail.points().size(); ++i) {
    EXPECT_GE((trail.points()[i] - trail.points()[i - 1]).norm(), Trail::kStep_m - 1e-12);
  }
  EXPECT_GT(trail.points().back().x(), 3.0 - Trail::kStep_m);
  // The oldest points are dropped while the rest still covers 1 m.
  EXPECT_GE(trail.length_m(), 1.0);
  EXPECT_LT(trail.length_m(), 1.0 + 2 * Trail::kStep_m + 1e-9);
  EXPECT_NEAR(trail.points().front().x(), trail.points().back().x() - trail.length_m(), 1e-9);
  // Turning on the spot adds nothing.
  const size_t before = trail.points().size();
  trail.Record(trail.points().back() + Eigen::Vector2d(0.005, 0.0), 1.0);
  EXPECT_EQ(trail.points().size(), before);
  // A length of 0 keeps nothing.
  trail.Record({3.5, 0.0}, 0.0);
  EXPECT_TRUE(trail.empty());
  EXPECT_EQ(trail.length_m(), 0.0);
}

TEST(TrailTest, ReversedRunsFromTheRobotBackToTheOldestPoint) {
  Trail trail;
  for (int k = 0; k <= 10; ++k) trail.Record({0.1 * k, 0.0}, 5.0);
  trail.Record({1.0, 0.5}, 5.0);  // the robot turned left at the end
  const std::vector<Eigen::Vector2d> back = trail.Reversed({1.0, 0.6});
  ASSERT_EQ(back.size(), trail.points().size() + 1);
  EXPECT_EQ(back.front(), Eigen::Vector2d(1.0, 0.6));
  EXPECT_EQ(back[1], Eigen::Vector2d(1.0, 0.5));
  EXPECT_EQ(back.back(), Eigen::Vector2d(0.0, 0.0));
  // Where the robot stands on the newest point, that point is not repeated.
  EXPECT_EQ(trail.Reversed({1.0, 0.5}).size(), trail.points().size());
}

TEST(WayBackTest, FollowsTheDrivenWayBackUntilFarEnoughInAStraightLine) {
  // Driven east along y = 0 for 4 m, then north 1 m: the robot stands at (4, 1.1).
  std::vector<Eigen::Vector2d> driven;
  for (int k = 0; k <= 20; ++k) driven.emplace_back(0.2 * k, 0.0);
  for (int k = 1; k <= 5; ++k) driven.emplace_back(4.0, 0.2 * k);
  const Eigen::Vector2d robot(4.0, 1.15);
  const std::vector<Eigen::Vector2d> way = WayBack(driven, robot, 2.0);
  ASSERT_GE(way.size(), 3u);
  EXPECT_EQ(way.front(), robot);
  EXPECT_EQ(way[1], driven[25]);  // (4, 1): back down the way it came, not across
  EXPECT_EQ(way[5], driven[21]);  // (4, 0.2)
  // It ends at the first driven point 2 m away, (2.2, 0): 2.14 m ((2.4, 0): 1.97 m).
  EXPECT_GE((way.back() - robot).norm(), 2.0);
  EXPECT_EQ(way.back(), driven[11]);
  for (size_t i = 0; i + 1 < way.size(); ++i) EXPECT_LT((way[i] - robot).norm(), 2.0) << i;
  // Nothing driven that far: no way back.
  EXPECT_TRUE(WayBack(driven, robot, 10.0).empty());
  EXPECT_TRUE(WayBack({}, robot, 0.5).empty());
}

TEST(WayBackTest, ErasesTheLoopsOfTurningAndCreepingAboutInOnePlace) {
  // In along x to (3, 0), then 600 nodes of turning on the spot and creeping
  // a few cm to and fro (a pocket the robot could not leave), once 0.3 m out
  // and back, ending 4 cm from where it came in.
  std::vector<Eigen::Vector2d> driven;
  for (int k = 0; k <= 15; ++k) driven.emplace_back(0.2 * k, 0.0);
  const Eigen::Vector2d pocket(3.0, 0.0);
  for (int k = 0; k < 600; ++k) {
    const double a = 0.37 * k;
    driven.push_back(pocket + 0.04 * std::abs(std::sin(0.05 * k)) *
                                  Eigen::Vector2d(std::cos(a), std::sin(a)));
    if (k == 300) {  // and once 0.3 m out and back again
      for (const double y : {0.15, 0.3, 0.15}) driven.push_back(pocket + Eigen::Vector2d(0.0, y));
    }
  }
  const Eigen::Vector2d robot = pocket + Eigen::Vector2d(0.0, 0.04);
  const std::vector<Eigen::Vector2d> way = WayBack(driven, robot, 2.0);
  ASSERT_FALSE(way.empty());
  // The first point of the way in that lies 2 m away ends it.
  Eigen::Vector2d first_far = Eigen::Vector2d::Zero();
  for (int k = 15; k >= 0; --k) {
    if ((Eigen::Vector2d(0.2 * k, 0.0) - robot).norm() >= 2.0) {
      first_far = {0.2 * k, 0.0};
      break;
    }
  }
  EXPECT_EQ(way.back(), first_far);
  // The pocket's hundreds of nodes are gone: the robot, at most one point of
  // the pocket, and the way in back to (1, 0).
  EXPECT_LE(way.size(), 2u + 11u);
  for (size_t i = 0; i < way.size(); ++i) {
    for (size_t j = i + 1; j < way.size(); ++j) {
      EXPECT_GT((way[i] - way[j]).norm(), kLoopTolerance_m) << i << " " << j;
    }
  }
  double length_m = 0.0;
  for (size_t i = 0; i + 1 < way.size(); ++i) length_m += (way[i + 1] - way[i]).norm();
  EXPECT_LT(length_m, (first_far - robot).norm() + 0.2);
}

}  // namespace
}  // namespace scout::explore
