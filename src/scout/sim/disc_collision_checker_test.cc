#include "scout/sim/disc_collision_checker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "scout/sim/random.h"
#include "scout/sim/world_painter.h"

namespace scout::sim {
namespace {

// A 4 m x 3 m free room at 5 cm with a wall block, a single occupied cell and
// an unknown patch.
grid::OccupancyMap MakeClutteredMap() {
  grid::OccupancyMap map = MakeFilledMap(
      geometry::Box2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(4, 3)), 0.05, grid::CellState::kFree);
  FillBox(geometry::Box2d(Eigen::Vector2d(2.5, 0), Eigen::Vector2d(4, 1)),
          grid::CellState::kOccupied, &map);
  FillBox(geometry::Box2d(Eigen::Vector2d(1.0, 1.5), Eigen::Vector2d(1.05, 1.55)),
          grid::CellState::kOccupied, &map);
  FillBox(geometry::Box2d(Eigen::Vector2d(3.0, 2.0), Eigen::Vector2d(3.5, 2.4)),
          grid::CellState::kUnknown, &map);
  return map;
}

// Independent reference: the distance from 'p' to the nearest non-free square
// or to the outside of the map, by looking at every cell.
double BruteForceDistance(const grid::OccupancyMap& map, const Eigen::Vector2d& p) {
  const geometry::Box2d bounds = map.limits.Bounds();
  double best = std::min({p.x() - bounds.min.x(), bounds.max.x() - p.x(), p.y() - bounds.min.y(),
                          bounds.max.y() - p.y()});
  best = std::max(best, 0.0);
  const double res = map.limits.resolution();
  for (int64_t i = 0; i < map.limits.num_cells(); ++i) {
    if (map.cells[i] == grid::CellState::kFree) continue;
    const Eigen::Vector2d center = map.limits.CellCenter(map.limits.CellOfFlatIndex(i));
    const Eigen::Vector2d half(res / 2, res / 2);
    best = std::min(best, geometry::Box2d(center - half, center + half).DistanceTo(p));
  }
  return best;
}

TEST(DiscCollisionChecker, AgreesWithBruteForceEverywhere) {
  const grid::OccupancyMap map = MakeClutteredMap();
  const double radius_m = 0.2;
  const DiscCollisionChecker checker(map, radius_m);
  std::mt19937_64 rng(3);
  int collisions = 0;
  for (int i = 0; i < 4000; ++i) {
    const Eigen::Vector2d p(UniformReal(rng, -0.1, 4.1), UniformReal(rng, -0.1, 3.1));
    const bool expected = BruteForceDistance(map, p) < radius_m;
    ASSERT_EQ(checker.Collides(p), expected) << "at " << p.transpose();
    collisions += expected ? 1 : 0;
  }
  // Both outcomes are exercised.
  EXPECT_GT(collisions, 500);
  EXPECT_LT(collisions, 3500);
}

TEST(DiscCollisionChecker, TouchingIsNotOverlapping) {
  const grid::OccupancyMap map = MakeClutteredMap();
  const DiscCollisionChecker checker(map, 0.2);
  // The wall block's left face is x = 2.5; the room's bottom wall is y = 0.
  EXPECT_FALSE(checker.Collides(Eigen::Vector2d(2.3, 0.5)));
  EXPECT_TRUE(checker.Collides(Eigen::Vector2d(2.3001, 0.5)));
  EXPECT_FALSE(checker.Collides(Eigen::Vector2d(1.5, 0.2)));
  EXPECT_TRUE(checker.Collides(Eigen::Vector2d(1.5, 0.1999)));
  // Near the single occupied cell's corner (1.05, 1.55), diagonally.
  const Eigen::Vector2d corner(1.05, 1.55);
  const Eigen::Vector2d diagonal = Eigen::Vector2d(1, 1).normalized();
  EXPECT_FALSE(checker.Collides(corner + 0.2001 * diagonal));
  EXPECT_TRUE(checker.Collides(corner + 0.1999 * diagonal));
}

TEST(DiscCollisionChecker, OutsideTheMapCollides) {
  const DiscCollisionChecker checker(MakeClutteredMap(), 0.2);
  EXPECT_TRUE(checker.Collides(Eigen::Vector2d(-1.0, 1.0)));
  EXPECT_TRUE(checker.Collides(Eigen::Vector2d(2.0, 3.5)));
}

TEST(DiscCollisionChecker, RejectsNonPositiveRadius) {
  EXPECT_THROW(DiscCollisionChecker(MakeClutteredMap(), 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace scout::sim
