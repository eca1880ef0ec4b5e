#include "scout/io/plan_picture.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "scout/grid/image.h"
#include "scout/grid/test_temp_directory.h"

namespace scout::io {
namespace {

// 100 x 60 cells of 0.1 m: free for x < 50, a wall at x = 50, unknown beyond.
grid::OccupancyMap HalfKnownMap() {
  grid::OccupancyMap map;
  map.limits = grid::MapLimits(0.1, {0.0, 0.0}, 100, 60);
  map.cells.assign(100 * 60, grid::CellState::kUnknown);
  for (int y = 0; y < 60; ++y) {
    for (int x = 0; x < 50; ++x) map.set({x, y}, grid::CellState::kFree);
    map.set({50, y}, grid::CellState::kOccupied);
  }
  return map;
}

TEST(WritePlanPicture, DrawsTheMapAroundThePlanWithRobotGoalAndPath) {
  const grid::TestTempDirectory dir;
  const grid::OccupancyMap map = HalfKnownMap();
  PlannedGoal planned;
  planned.robot = {2.05, 2.05};   // cell (20, 20)
  planned.goal = {4.05, 2.05};    // cell (40, 20)
  planned.target = {3.85, 2.05};  // cell (38, 20)
  planned.path = {planned.robot, {3.05, 3.05}, planned.target};
  planned.scan = {{1.05, 4.05}, {50.05, 4.05}};  // cell (10, 40); the other far off
  const auto path = dir.path() / "plan.png";
  WritePlanPicture(map, planned, path);
  const grid::Image image = grid::ReadImage(path);
  // Cells 20..40 x 20..30 plus 40 cells of margin, clipped to the map:
  // columns 0..80, rows 0..59; 4 pixels per cell, north up.
  ASSERT_EQ(image.width, 81 * 4);
  ASSERT_EQ(image.height, 60 * 4);
  ASSERT_EQ(image.channels, 3);
  const auto cell = [&](int x, int y) { return image.at(x * 4 + 1, (59 - y) * 4 + 1); };
  const auto is = [](const uint8_t* px, int r, int g, int b) {
    return px[0] == r && px[1] == g && px[2] == b;
  };
  EXPECT_TRUE(is(cell(20, 20), 0, 170, 0));      // robot
  EXPECT_TRUE(is(cell(40, 20), 230, 0, 0));      // goal
  EXPECT_TRUE(is(cell(38, 20), 255, 150, 0));    // target
  EXPECT_TRUE(is(cell(25, 25), 0, 90, 255));     // on the path's first leg
  EXPECT_TRUE(is(cell(10, 40), 220, 0, 220));    // a scan return
  EXPECT_TRUE(is(cell(10, 50), 255, 255, 255));  // free
  EXPECT_TRUE(is(cell(50, 50), 0, 0, 0));        // the wall
  EXPECT_TRUE(is(cell(70, 50), 200, 200, 200));  // unknown
}

TEST(WritePlanPicture, ALongPlanGetsFewerPixelsPerCell) {
  const grid::TestTempDirectory dir;
  grid::OccupancyMap map;
  map.limits = grid::MapLimits(0.1, {0.0, 0.0}, 2000, 100);
  map.cells.assign(2000 * 100, grid::CellState::kFree);
  PlannedGoal planned;
  planned.robot = {1.05, 5.05};
  planned.goal = planned.target = {198.05, 5.05};
  planned.path = {planned.robot, planned.goal};
  const auto path = dir.path() / "long.png";
  WritePlanPicture(map, planned, path);
  const grid::Image image = grid::ReadImage(path);
  // Columns 0..1999 (clipped), rows 10..90 (row 50 and 40 of margin):
  // 2400 / 2000 rounds down to 1 pixel per cell.
  EXPECT_EQ(image.width, 2000);
  EXPECT_EQ(image.height, 81);
  EXPECT_EQ(image.at(1000, 90 - 50)[2], 255);  // the path, blue
  EXPECT_EQ(image.at(1000, 90 - 50)[0], 0);
}

TEST(WritePlanPicture, AnEmptyMapIsAnError) {
  const grid::TestTempDirectory dir;
  EXPECT_THROW(WritePlanPicture(grid::OccupancyMap{}, PlannedGoal{}, dir.path() / "p.png"),
               std::invalid_argument);
}

}  // namespace
}  // namespace scout::io
