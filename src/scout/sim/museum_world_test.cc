#include "scout/sim/museum_world.h"

#include <gtest/gtest.h>

#include "scout/sim/clearance.h"
#include "scout/sim/test_reachability.h"

namespace scout::sim {
namespace {

constexpr double kMuseumInflationRadiusM = 0.40;

TEST(MuseumWorld, IsAtLeast150MetresAcross) {
  const World world = GenerateMuseumWorld(1);
  EXPECT_EQ(world.name, "museum");
  const geometry::Box2d bounds = world.map.limits.Bounds();
  EXPECT_GE(bounds.max.x() - bounds.min.x(), 150.0);
  EXPECT_EQ(world.map.at(world.map.limits.CellContaining(world.start)), grid::CellState::kFree);
}

TEST(MuseumWorld, IsDeterministicPerSeed) {
  const MuseumLayout a = PlanMuseumLayout(4);
  const MuseumLayout b = PlanMuseumLayout(4);
  const MuseumLayout c = PlanMuseumLayout(5);
  ASSERT_EQ(a.exhibits.size(), b.exhibits.size());
  for (size_t i = 0; i < a.exhibits.size(); ++i) {
    EXPECT_EQ(a.exhibits[i].min, b.exhibits[i].min);
    EXPECT_EQ(a.exhibits[i].max, b.exhibits[i].max);
  }
  EXPECT_EQ(a.openings.size(), b.openings.size());
  const bool same = a.exhibits.size() == c.exhibits.size() &&
                    (a.exhibits.empty() || a.exhibits[0].min == c.exhibits[0].min);
  EXPECT_FALSE(same);
}

TEST(MuseumWorld, HasBigHallsWithObstacles) {
  const MuseumLayout layout = PlanMuseumLayout(1);
  EXPECT_GE(layout.halls.size(), 12u);
  for (const geometry::Box2d& hall : layout.halls) {
    EXPECT_GE((hall.max - hall.min).minCoeff(), 15.0);
    EXPECT_LE((hall.max - hall.min).maxCoeff(), 30.0);
  }
  EXPECT_GE(layout.exhibits.size(), layout.halls.size());
}

TEST(MuseumWorld, EveryHallIsReachableByTheInflatedRobot) {
  const MuseumWorldOptions options;
  const MuseumLayout layout = PlanMuseumLayout(2, options);
  const grid::OccupancyMap map = RenderMuseumLayout(layout, options.resolution_m);
  const std::vector<float> clearance = ComputeClearance(map);
  const std::vector<uint8_t> reached =
      ReachableCells(map, clearance, ChooseStartPosition(map, "museum"),
                     [](float c) { return c > kMuseumInflationRadiusM; });
  for (size_t h = 0; h < layout.halls.size(); ++h) {
    EXPECT_TRUE(AnyCellIn(map, reached, layout.halls[h])) << "hall " << h;
  }
  for (const geometry::Box2d& corridor : layout.corridors) {
    EXPECT_TRUE(AnyCellIn(map, reached, corridor));
  }
}

}  // namespace
}  // namespace scout::sim
