#include "scout/sim/office_world.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "scout/common/error.h"
#include "scout/sim/clearance.h"
#include "scout/sim/test_reachability.h"

namespace scout::sim {
namespace {

constexpr double kRobotRadiusM = 0.20;
constexpr double kInflationRadiusM = 0.40;  // robot + safety margin (ALGORITHMS §2)

TEST(OfficeWorld, IsDeterministicPerSeed) {
  const World a = GenerateOfficeWorld(11);
  const World b = GenerateOfficeWorld(11);
  EXPECT_EQ(a.map.cells, b.map.cells);
  EXPECT_EQ(a.start, b.start);
  EXPECT_NE(a.map.cells, GenerateOfficeWorld(12).map.cells);
}

TEST(OfficeWorld, HasRequestedSizeAndFreeStart) {
  const World world = GenerateOfficeWorld(1);
  EXPECT_EQ(world.name, "office");
  EXPECT_EQ(world.map.limits.width(), 800);
  EXPECT_EQ(world.map.limits.height(), 600);
  EXPECT_EQ(world.map.at(world.map.limits.CellContaining(world.start)), grid::CellState::kFree);
}

TEST(OfficeWorld, CorridorsFormAFreeLoop) {
  for (uint64_t seed : {1, 2, 3}) {
    const OfficeWorldOptions options;
    const OfficeLayout layout = PlanOfficeLayout(seed, options);
    const grid::OccupancyMap map = RenderOfficeLayout(layout, options.resolution_m);
    const std::vector<float> clearance = ComputeClearance(map);
    ASSERT_EQ(layout.corridors.size(), 4u);
    // The rectangle through the corridor centres keeps half the corridor
    // width (less one cell) from anything that is not free, all the way round.
    const Eigen::Vector2d lo(layout.corridors[2].Center().x(), layout.corridors[0].Center().y());
    const Eigen::Vector2d hi(layout.corridors[3].Center().x(), layout.corridors[1].Center().y());
    const Eigen::Vector2d corners[5] = {lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}, lo};
    const double step_m = 0.5 * options.resolution_m;
    const float min_clearance =
        static_cast<float>(0.5 * options.corridor_width_m - options.resolution_m);
    for (int side = 0; side < 4; ++side) {
      const Eigen::Vector2d delta = corners[side + 1] - corners[side];
      const int steps = static_cast<int>(delta.norm() / step_m);
      for (int i = 0; i <= steps; ++i) {
        const Eigen::Vector2d p = corners[side] + delta * (static_cast<double>(i) / steps);
        ASSERT_GE(clearance[map.limits.FlatIndex(map.limits.CellContaining(p))], min_clearance)
            << "seed " << seed << " at " << p.transpose();
      }
    }
  }
}

TEST(OfficeWorld, EveryRoomIsReachableByTheBareRobot) {
  for (uint64_t seed : {1, 2, 3, 4, 5}) {
    const OfficeWorldOptions options;
    const OfficeLayout layout = PlanOfficeLayout(seed, options);
    const grid::OccupancyMap map = RenderOfficeLayout(layout, options.resolution_m);
    const std::vector<uint8_t> reached = ReachableCells(map, ComputeClearance(map), layout.start,
                                                        [](float c) { return c >= kRobotRadiusM; });
    EXPECT_GE(layout.rooms.size(), 20u);
    for (size_t r = 0; r < layout.rooms.size(); ++r) {
      EXPECT_TRUE(AnyCellIn(map, reached, layout.rooms[r].interior))
          << "seed " << seed << " room " << r;
    }
  }
}

TEST(OfficeWorld, SomeRoomsAreBehindGapsNarrowerThanTheInflatedRobot) {
  for (uint64_t seed : {1, 2, 3}) {
    const OfficeWorldOptions options;
    const OfficeLayout layout = PlanOfficeLayout(seed, options);
    const grid::OccupancyMap map = RenderOfficeLayout(layout, options.resolution_m);
    const std::vector<float> clearance = ComputeClearance(map);
    // The inflated robot passes only where no obstacle is within the inflation radius.
    const std::vector<uint8_t> inflated =
        ReachableCells(map, clearance, layout.start, [](float c) { return c > kInflationRadiusM; });
    const std::vector<uint8_t> bare =
        ReachableCells(map, clearance, layout.start, [](float c) { return c >= kRobotRadiusM; });
    int ajar = 0;
    for (const OfficeRoom& room : layout.rooms) {
      if (!room.door_ajar) continue;
      ++ajar;
      const Eigen::Vector2d size = room.doorway.max - room.doorway.min;
      EXPECT_LT(std::min(size.x(), size.y()), 2.0 * kInflationRadiusM);
      EXPECT_TRUE(AnyCellIn(map, bare, room.interior));
      EXPECT_FALSE(AnyCellIn(map, inflated, room.interior)) << "seed " << seed;
    }
    EXPECT_GE(ajar, 1);
  }
}

TEST(OfficeWorld, HasFurniture) {
  const OfficeLayout layout = PlanOfficeLayout(1);
  EXPECT_GE(layout.furniture.size(), 2 * layout.rooms.size());
}

TEST(OfficeWorld, RejectsABuildingTooSmallForItsRooms) {
  OfficeWorldOptions options;
  options.height_m = 15.0;
  EXPECT_THROW(GenerateOfficeWorld(1, options), InputError);
}

}  // namespace
}  // namespace scout::sim
