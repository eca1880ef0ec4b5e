#include "scout/frontier/local_frontiers.h"

#include <gtest/gtest.h>

#include "scout/frontier/test_grids.h"

namespace scout::frontier {
namespace {

using testing::DrawGrid;

LocalFrontier Extract(const grid::ProbabilityGrid& g, std::vector<Eigen::Vector2d> origins,
                      double inflation_m) {
  return ExtractReachableFrontier(g.States(), g.limits(), origins, inflation_m);
}

// A 1 m x 1 m room at 0.1 m: walls all round except an opening to unknown on the right.
std::vector<std::string> RoomWithOpening() {
  return {
      "############",  //
      "#.........??",  //
      "#.........??",  //
      "#.........??",  //
      "#.........??",  //
      "#.........??",  //
      "#.........??",  //
      "#.........??",  //
      "#.........??",  //
      "############",  //
  };
}

TEST(FrontierCellMask, MarksFreeCellsWithAnUnknownNeighbour) {
  const auto g = DrawGrid({"...?", "....", "####"}, 0.1);
  const std::vector<uint8_t> mask = FrontierCellMask(g->States(), g->limits());
  // Row y=2 (top): x=2 touches '?' at (3,2); x=3 is unknown itself.
  EXPECT_EQ(mask[g->limits().FlatIndex({2, 2})], 1);
  EXPECT_EQ(mask[g->limits().FlatIndex({3, 2})], 0);
  // (2,1) touches (3,2) diagonally; (3,1) has neighbours outside the grid (unknown).
  EXPECT_EQ(mask[g->limits().FlatIndex({2, 1})], 1);
  EXPECT_EQ(mask[g->limits().FlatIndex({3, 1})], 1);
  // Occupied cells are never frontier cells.
  EXPECT_EQ(mask[g->limits().FlatIndex({1, 0})], 0);
}

TEST(ExtractReachableFrontier, FindsTheOpeningOfARoomWithoutInflation) {
  const auto g = DrawGrid(RoomWithOpening(), 0.1);
  const LocalFrontier f = Extract(*g, {{0.45, 0.45}}, 0.0);
  // The free column x=9 (rows 1..8) touches the unknown column x=10.
  ASSERT_EQ(f.cells.size(), 8u);
  for (const grid::CellIndex& c : f.cells) EXPECT_EQ(c.x, 9);
  EXPECT_NEAR(f.points_m[0].x(), 0.95, 1e-9);
}

TEST(ExtractReachableFrontier, DoorwayNarrowerThanRobotMakesTheRoomBehindUnreachable) {
  // Left room (reachable) | wall with a 0.3 m doorway | right room opening to unknown.
  const std::vector<std::string> rows = {
      "###########################",  //
      "#..........#..............?",  //
      "#..........#..............?",  //
      "#..........#..............?",  //
      "#..........#..............?",  //
      "#.........................?",  //
      "#.........................?",  //
      "#.........................?",  //
      "#..........#..............?",  //
      "#..........#..............?",  //
      "#..........#..............?",  //
      "#..........#..............?",  //
      "###########################",  //
  };
  const auto g = DrawGrid(rows, 0.1);
  // Without inflation the robot would "reach" the right room's frontier.
  EXPECT_FALSE(Extract(*g, {{0.55, 0.65}}, 0.0).cells.empty());
  // Doorway 0.3 m < 2 * 0.2 m: blocked for an inflation radius of 0.2 m.
  EXPECT_TRUE(Extract(*g, {{0.55, 0.65}}, 0.2).cells.empty());
  // From inside the right room the frontier is reachable.
  EXPECT_FALSE(Extract(*g, {{1.95, 0.65}}, 0.2).cells.empty());
}

TEST(ExtractReachableFrontier, SeedNextToAWallStartsFromTheNearestOpenCell) {
  const auto g = DrawGrid(RoomWithOpening(), 0.1);
  // 0.1 m from the left wall, inside the 0.2 m blocked band.
  const LocalFrontier from_wall = Extract(*g, {{0.16, 0.45}}, 0.2);
  EXPECT_FALSE(from_wall.cells.empty());
  // A seed in the wall itself with no open cell within the radius seeds nothing.
  const auto tight = DrawGrid({"#######", "#.....?", "#######"}, 0.1);
  EXPECT_TRUE(Extract(*tight, {{0.35, 0.15}}, 0.2).cells.empty());
  // A seed outside the grid seeds nothing.
  EXPECT_TRUE(Extract(*g, {{-5.0, -5.0}}, 0.2).cells.empty());
}

TEST(ExtractReachableFrontier, InflatedFrontierExcludesCellsHuggingWalls) {
  const auto g = DrawGrid(RoomWithOpening(), 0.1);
  const LocalFrontier f = Extract(*g, {{0.45, 0.45}}, 0.2);
  // Rows within 0.2 m of the top/bottom walls are blocked: rows 1 and 8 are out.
  ASSERT_FALSE(f.cells.empty());
  for (const grid::CellIndex& c : f.cells) {
    EXPECT_GE(c.y, 3);
    EXPECT_LE(c.y, 6);
  }
}

}  // namespace
}  // namespace scout::frontier
