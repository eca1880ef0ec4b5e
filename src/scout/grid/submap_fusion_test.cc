#include "scout/grid/submap_fusion.h"

#include <gtest/gtest.h>

#include <numbers>

namespace scout::grid {
namespace {

ProbabilityGrid Uniform(int n, float p) {
  ProbabilityGrid g(MapLimits(0.1, {0, 0}, n, n));
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) g.SetProbability({x, y}, p);
  }
  return g;
}

TEST(FuseSubmaps, UnknownWhereNoSubmapKnowsAndLogOddsVoteElsewhere) {
  const ProbabilityGrid free_a = Uniform(10, 0.2f);    // covers [0, 1]^2
  const ProbabilityGrid occupied = Uniform(10, 0.6f);  // placed at [0.5, 1.5] x [0, 1]
  ProbabilityGrid free_b = Uniform(10, 0.45f);         // placed at [1, 2] x [0, 1]
  const OccupancyMap fused = FuseSubmaps({{&free_a, geometry::Rigid2d()},
                                          {&occupied, geometry::Rigid2d(0.5, 0, 0)},
                                          {&free_b, geometry::Rigid2d(1.0, 0, 0)}},
                                         0.1);
  ASSERT_EQ(fused.limits.width(), 20);
  ASSERT_EQ(fused.limits.height(), 10);
  EXPECT_EQ(fused.at({2, 5}), CellState::kFree);       // only free_a
  EXPECT_EQ(fused.at({7, 5}), CellState::kFree);       // logit(0.2) + logit(0.6) < 0
  EXPECT_EQ(fused.at({12, 5}), CellState::kOccupied);  // logit(0.6) + logit(0.45) > 0
  EXPECT_EQ(fused.at({17, 5}), CellState::kFree);      // only free_b
}

TEST(FuseSubmaps, RotatedSubmapLandsWhereItsPoseSays) {
  ProbabilityGrid g(MapLimits(0.1, {0, 0}, 10, 2));
  for (int x = 0; x < 10; ++x) g.SetProbability({x, 0}, 0.9f);  // a 1 m wall along x
  // Rotated by 90 degrees about the origin, the wall runs along +y at x in [-0.1, 0].
  const OccupancyMap fused =
      FuseSubmaps({{&g, geometry::Rigid2d(0, 0, std::numbers::pi / 2)}}, 0.1);
  const CellIndex c = fused.limits.CellContaining({-0.05, 0.55});
  EXPECT_EQ(fused.at(c), CellState::kOccupied);
  EXPECT_EQ(fused.at(fused.limits.CellContaining({-0.15, 0.55})), CellState::kUnknown);
}

TEST(FuseSubmaps, NoSubmapsGiveAnEmptyMap) {
  EXPECT_EQ(FuseSubmaps({}, 0.05).limits.num_cells(), 0);
}

}  // namespace
}  // namespace scout::grid
