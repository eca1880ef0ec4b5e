// End-to-end tests of `scout frontiers`: the reachable frontier and the
// navigation points of a saved map, from a given robot position.

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "apps/scout/cli_test_util.h"
#include "scout/grid/map_io.h"

namespace {

namespace fs = std::filesystem;
using scout::grid::CellState;
using scout::testing::RunScout;

std::vector<std::string> Lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

class FrontiersCli : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    dir_ = fs::temp_directory_path() / ("scout_frontiers_test_" + std::to_string(rd()));
    fs::create_directories(dir_);
    // 10 m x 8 m at 5 cm, unknown but for a 1.5 m wide corridor from x = 1 m
    // to 9 m (y 3.0-4.5 m) whose ends open into unknown space, and a room
    // above it whose only way in is a gap of one cell in the corridor's wall.
    scout::grid::OccupancyMap map;
    map.limits = scout::grid::MapLimits(0.05, {0, 0}, 200, 160);
    map.cells.assign(map.limits.num_cells(), CellState::kUnknown);
    const auto fill = [&](int x0, int y0, int x1, int y1, CellState s) {
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) map.set({x, y}, s);
      }
    };
    fill(20, 57, 179, 59, CellState::kOccupied);
    fill(20, 90, 179, 92, CellState::kOccupied);
    fill(20, 60, 179, 89, CellState::kFree);
    fill(87, 93, 89, 140, CellState::kOccupied);
    fill(121, 93, 123, 140, CellState::kOccupied);
    fill(90, 93, 120, 140, CellState::kFree);
    fill(105, 90, 105, 92, CellState::kFree);
    scout::grid::WriteMapServerMap(map, dir_ / "corridor.yaml");
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Map() const { return (dir_ / "corridor.yaml").string(); }
  fs::path dir_;
};

TEST_F(FrontiersCli, RanksTheCorridorEndsAndLeavesTheSealedRoomOut) {
  const fs::path out = dir_ / "out";
  const scout::testing::CliResult r =
      RunScout("frontiers " + Map() + " --robot 3,3.75 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("2 navigation points; best (1.03, "), std::string::npos) << r.output;
  for (const char* name :
       {"summary.json", "navigation_points.csv", "frontier_points.csv", "map.png", "report.html"}) {
    EXPECT_TRUE(fs::is_regular_file(out / name)) << name;
  }
  std::ifstream in(out / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(in);
  EXPECT_EQ(s["navigation_points"]["count"], 2);
  EXPECT_FALSE(s["navigation_points"]["robot_boxed_in"].get<bool>());
  // Every frontier point is reachable: at a corridor end, never in the room.
  const std::vector<std::string> points = Lines(out / "frontier_points.csv");
  ASSERT_GT(points.size(), 1u);
  EXPECT_EQ(points[0], "x_m,y_m");
  EXPECT_EQ(static_cast<int>(points.size()) - 1, s["frontier_points"].get<int>());
  for (size_t k = 1; k < points.size(); ++k) {
    double x = 0, y = 0;
    ASSERT_EQ(std::sscanf(points[k].c_str(), "%lf,%lf", &x, &y), 2) << points[k];
    EXPECT_TRUE(x < 1.1 || x > 8.9) << points[k];
    EXPECT_LT(y, 4.5) << points[k];
  }
  // The near end first (2 m of path), then the far one (6 m).
  const std::vector<std::string> goals = Lines(out / "navigation_points.csv");
  ASSERT_EQ(goals.size(), 3u);
  double rank = 0, x1 = 0, y1 = 0, cost1 = 0, x2 = 0, y2 = 0, cost2 = 0;
  ASSERT_EQ(std::sscanf(goals[1].c_str(), "%lf,%lf,%lf,%lf", &rank, &x1, &y1, &cost1), 4);
  ASSERT_EQ(std::sscanf(goals[2].c_str(), "%lf,%lf,%lf,%lf", &rank, &x2, &y2, &cost2), 4);
  EXPECT_NEAR(x1, 1.025, 1e-9);
  EXPECT_NEAR(x2, 8.975, 1e-9);
  EXPECT_NEAR(cost1, 2.0, 0.2);
  EXPECT_NEAR(cost2, 6.0, 0.2);
}

TEST_F(FrontiersCli, ARobotInUnknownSpaceReachesNothing) {
  const fs::path out = dir_ / "nowhere";
  const scout::testing::CliResult r =
      RunScout("frontiers " + Map() + " --robot 5,7.8 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("0 navigation points"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("the robot's disc fits nowhere near"), std::string::npos) << r.output;
}

TEST_F(FrontiersCli, BadInputIsAClearErrorWithoutOutputs) {
  const fs::path out = dir_ / "bad";
  const auto expect_error = [&](const std::string& args, const std::string& message) {
    const scout::testing::CliResult r = RunScout("frontiers " + args + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
    EXPECT_FALSE(fs::exists(out)) << args;
  };
  expect_error(Map() + " --robot 30,2", "--robot 30,2 lies outside the map");
  expect_error(Map() + " --robot 3:2", "--robot '3:2': expected X,Y in metres");
  expect_error(Map(), "--robot is required");
  expect_error((dir_ / "missing.yaml").string() + " --robot 1,1", "missing.yaml");
}

}  // namespace
