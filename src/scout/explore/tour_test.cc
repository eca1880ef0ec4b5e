#include "scout/explore/tour.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>

#include "scout/explore/goal_policies.h"
#include "scout/explore/test_maps.h"

namespace scout::explore {
namespace {

using testing::MapBuilder;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Three points on a line through the robot (at 0): A at +1.5, B at -1, C at -2.
// Going to the nearest (B) first leaves A behind: 1 + 1 + 3.5 = 5.5 m; A first
// then B and C: 1.5 + 2.5 + 1 = 5 m.
TEST(TourTest, OpenTourLengthsOnALine) {
  const std::vector<double> first = {1.5, 1.0, 2.0};
  const std::vector<std::vector<double>> d = {{0, 2.5, 3.5}, {2.5, 0, 1.0}, {3.5, 1.0, 0}};
  const std::vector<double> length = OpenTourLengths(first, d);
  ASSERT_EQ(length.size(), 3u);
  EXPECT_DOUBLE_EQ(length[0], 5.0);
  EXPECT_DOUBLE_EQ(length[1], 5.5);  // B, C, then A
  EXPECT_DOUBLE_EQ(length[2], 5.5);  // C, B, then A
}

TEST(TourTest, APairWithoutAPathGoesThroughTheRobot) {
  const std::vector<double> length = OpenTourLengths({1.0, 2.0}, {{0, kInf}, {kInf, 0}});
  EXPECT_DOUBLE_EQ(length[0], 1.0 + 3.0);
  EXPECT_DOUBLE_EQ(length[1], 2.0 + 3.0);
}

TEST(TourTest, TooManyCandidatesAreRejected) {
  const int n = kMaxTourPoints + 1;
  EXPECT_THROW(OpenTourLengths(std::vector<double>(n, 1.0),
                               std::vector<std::vector<double>>(n, std::vector<double>(n, 1.0))),
               std::invalid_argument);
  EXPECT_TRUE(OpenTourLengths({}, {}).empty());
}

// Held-Karp equals trying every order, on random asymmetric-free instances.
TEST(TourTest, OpenTourLengthsEqualBruteForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-10.0, 10.0);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial % 7;
    std::vector<Eigen::Vector2d> p(n);
    for (Eigen::Vector2d& q : p) q = {coord(rng), coord(rng)};
    std::vector<double> first(n);
    std::vector<std::vector<double>> d(n, std::vector<double>(n));
    for (int i = 0; i < n; ++i) {
      first[i] = p[i].norm();
      for (int j = 0; j < n; ++j) d[i][j] = (p[i] - p[j]).norm();
    }
    const std::vector<double> length = OpenTourLengths(first, d);
    std::vector<double> best(n, kInf);
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    do {
      double l = first[order[0]];
      for (int k = 1; k < n; ++k) l += d[order[k - 1]][order[k]];
      best[order[0]] = std::min(best[order[0]], l);
    } while (std::next_permutation(order.begin(), order.end()));
    for (int i = 0; i < n; ++i) EXPECT_NEAR(length[i], best[i], 1e-9) << "trial " << trial;
  }
}

// A 6 x 4 m room (5 cm cells) split by a wall from the bottom to 2.5 m, so
// the way between the two lower halves runs over the top.
struct WallScene {
  MapBuilder b{120, 80, 0.05};
  explicit WallScene(bool wall) {
    b.Wall(0, 0, 119, 79).Free(1, 1, 118, 78);
    if (wall) b.Wall(60, 0, 60, 50);
  }
};

TEST(TourTest, CoarsePathDistancesGoRoundWallsAndAgreeWithTheFineField) {
  for (const bool wall : {false, true}) {
    WallScene s(wall);
    const PlanningMap map(s.b.map(), TraversabilityOptions{});
    const grid::CellIndex a{30, 10}, b{90, 10};
    ASSERT_TRUE(map.Traversable(a) && map.Traversable(b));
    const auto d = CoarsePathDistances(map, {a, b}, 0.2);
    EXPECT_EQ(d[0][0], 0.0);
    EXPECT_EQ(d[0][1], d[1][0]);
    // The fine field's path, the same step rule at 5 cm.
    const PathDistanceField fine(map, s.b.At(30, 10));
    const double fine_m = fine.at(b);
    if (wall) {
      EXPECT_GT(fine_m, 6.0);  // 3 m straight, over the wall's end at 2.5 m and back
    } else {
      EXPECT_NEAR(fine_m, 3.0, 0.01);
    }
    EXPECT_NEAR(d[0][1], fine_m, 0.1 * fine_m) << "wall " << wall;
  }
}

TEST(TourTest, CandidatesOutsideTheOpenCellsHaveNoDistance) {
  WallScene s(true);
  const PlanningMap map(s.b.map(), TraversabilityOptions{});
  // (60, 20) is in the wall; (-5, 3) is outside the map.
  const auto d = CoarsePathDistances(map, {{30, 10}, {60, 20}, {-5, 3}}, 0.2);
  EXPECT_EQ(d[0][1], kInf);
  EXPECT_EQ(d[0][2], kInf);
  EXPECT_EQ(d[1][2], kInf);
}

// A corridor 20 m long with the robot in the middle (x = 10 m) and three known
// navigation points without unknown space around them (equal information
// gain): 2.5 m to the left, 2 m and 4 m to the right. By revenue the robot
// goes right first and leaves the left point for last (2 + 2 + 6.5 m); the
// tour goes left first (2.5 + 4.5 + 2 m).
TEST(TourTest, ScoutPolicyWithToursTakesTheLonePointFirst) {
  MapBuilder b(200, 20);
  b.Wall(0, 0, 199, 19).Free(1, 1, 198, 18);
  const std::vector<Eigen::Vector2d> frontier = {b.At(75, 10), b.At(120, 10), b.At(140, 10)};
  const Eigen::Vector2d robot = b.At(100, 10);
  const PlanningMap map(b.map(), TraversabilityOptions{});
  const PathDistanceField field(map, robot);
  const auto rank = [&](int tour_points) {
    GoalPolicyOptions options;
    options.navigation.tour_points = tour_points;
    PolicyInput in;
    in.map = &map;
    in.distances = &field;
    in.frontier = &frontier;
    in.robot = robot;
    return MakeGoalPolicy("scout", options)->Rank(in);
  };
  const auto by_revenue = rank(0);
  ASSERT_EQ(by_revenue.size(), 3u);
  EXPECT_EQ(by_revenue[0].position, b.At(120, 10));
  const auto by_tour = rank(3);
  ASSERT_EQ(by_tour.size(), 3u);
  EXPECT_EQ(by_tour[0].position, b.At(75, 10));
  // Within a coarse cell (0.2 m) per leg.
  EXPECT_NEAR(by_tour[0].score, -9.0, 0.6);
  for (size_t i = 1; i < by_tour.size(); ++i) EXPECT_GE(by_tour[i - 1].score, by_tour[i].score);
  // Ranking only the best two by revenue (2 m right, 2.5 m left) by tour:
  // right first (2 + 4.5 m against 2.5 + 4.5 m), and the far right point,
  // third by revenue, keeps its place below them.
  const auto two = rank(2);
  ASSERT_EQ(two.size(), 3u);
  EXPECT_EQ(two[0].position, b.At(120, 10));
  EXPECT_EQ(two[1].position, b.At(75, 10));
  EXPECT_EQ(two[2].position, b.At(140, 10));
  EXPECT_LT(two[2].score, two[1].score);
}

TEST(TourTest, TourPointsOutOfRangeAreRejected) {
  GoalPolicyOptions options;
  options.navigation.tour_points = 1;
  EXPECT_THROW(MakeGoalPolicy("scout", options), std::invalid_argument);
  options.navigation.tour_points = kMaxTourPoints + 1;
  EXPECT_THROW(MakeGoalPolicy("scout", options), std::invalid_argument);
}

}  // namespace
}  // namespace scout::explore
