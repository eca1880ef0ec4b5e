#include "scout/explore/scan_contradiction.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

namespace scout::explore {
namespace {

TEST(PathCrossesReturns, AReturnOnTheWayIsFound) {
  const std::vector<Eigen::Vector2d> path = {{0, 0}, {3, 0}, {3, 3}};
  EXPECT_TRUE(PathCrossesReturns(path, {{5, 5}, {3.05, 1.5}}, 0.1));
  EXPECT_TRUE(PathCrossesReturns(path, {{1.5, -0.09}}, 0.1));
}

TEST(PathCrossesReturns, ReturnsBesideThePathOrBeyondItsEndsAreNot) {
  const std::vector<Eigen::Vector2d> path = {{0, 0}, {3, 0}, {3, 3}};
  // A corridor's walls 0.25 m either side (the narrow margin), and a wall
  // 0.15 m past the path's end.
  EXPECT_FALSE(PathCrossesReturns(path, {{1, 0.25}, {1, -0.25}, {2.75, 1.5}, {3, 3.15}}, 0.1));
  EXPECT_FALSE(PathCrossesReturns(path, {}, 0.1));
  EXPECT_FALSE(PathCrossesReturns({}, {{0, 0}}, 0.1));
}

TEST(ThinToCells, KeepsTheFirstPointOfEachCell) {
  const std::vector<Eigen::Vector2d> points = {
      {0.01, 0.01}, {0.04, 0.02}, {0.06, 0.01}, {-0.01, 0.01}, {0.011, 0.012}};
  const std::vector<Eigen::Vector2d> kept = ThinToCells(points, 0.05);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[0], points[0]);
  EXPECT_EQ(kept[1], points[2]);
  EXPECT_EQ(kept[2], points[3]);
  EXPECT_EQ(ThinToCells(points, 0.0), points);
  EXPECT_TRUE(ThinToCells({}, 0.05).empty());
}

RC_GTEST_PROP(ThinToCellsProperty, EveryPointHasAKeptOneWithinACellDiagonal, ()) {
  const int n = *rc::gen::inRange(1, 200);
  const double cell_m = *rc::gen::inRange(1, 100) * 0.01;
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < n; ++i) {
    points.emplace_back(*rc::gen::inRange(-5000, 5000) * 1e-3,
                        *rc::gen::inRange(-5000, 5000) * 1e-3);
  }
  const std::vector<Eigen::Vector2d> kept = ThinToCells(points, cell_m);
  RC_ASSERT(!kept.empty());
  RC_ASSERT(kept.size() <= points.size());
  for (const Eigen::Vector2d& p : points) {
    double nearest = INFINITY;
    for (const Eigen::Vector2d& k : kept) nearest = std::min(nearest, (p - k).norm());
    RC_ASSERT(nearest <= cell_m * std::sqrt(2.0) + 1e-12);
  }
}

TEST(PathCrossesReturns, APathOfOnePointIsThatPoint) {
  EXPECT_TRUE(PathCrossesReturns({{1, 1}}, {{1.05, 1}}, 0.1));
  EXPECT_FALSE(PathCrossesReturns({{1, 1}}, {{1.2, 1}}, 0.1));
}

// Equals the distance to the nearest segment, computed point by point along
// each segment (finely enough that the tolerance covers the sampling).
RC_GTEST_PROP(PathCrossesReturns, AgreesWithSampledDistances, ()) {
  const auto coordinate = [] { return *rc::gen::inRange(-500, 500) / 100.0; };
  std::vector<Eigen::Vector2d> path(*rc::gen::inRange(2, 6));
  for (Eigen::Vector2d& p : path) p = {coordinate(), coordinate()};
  std::vector<Eigen::Vector2d> returns(*rc::gen::inRange(1, 20));
  for (Eigen::Vector2d& q : returns) q = {coordinate(), coordinate()};
  const double radius_m = *rc::gen::inRange(1, 100) / 100.0;
  double nearest = INFINITY;
  for (size_t i = 1; i < path.size(); ++i) {
    for (int k = 0; k <= 5000; ++k) {
      const Eigen::Vector2d p = path[i - 1] + (path[i] - path[i - 1]) * (k / 5000.0);
      for (const Eigen::Vector2d& q : returns) nearest = std::min(nearest, (p - q).norm());
    }
  }
  // Steps of at most 0.003 m put the sampled distance within 0.0015 m of the true one.
  RC_PRE(std::abs(nearest - radius_m) > 0.002);
  RC_ASSERT(PathCrossesReturns(path, returns, radius_m) == (nearest <= radius_m));
}

}  // namespace
}  // namespace scout::explore
