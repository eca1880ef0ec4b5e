#include "scout/explore/trail.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace scout::explore
