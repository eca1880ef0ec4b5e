#include "scout/sim/world.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <random>
#include <string>

#include "scout/common/error.h"
#include "scout/grid/map_io.h"
#include "scout/sim/clearance.h"
#include "scout/sim/make_world.h"
#include "scout/sim/world_painter.h"

namespace scout::sim {
namespace {

// A fresh temporary directory, removed with its contents on destruction.
class TempDirectory {
 public:
  TempDirectory() {
    std::random_device random;
    path_ = std::filesystem::temp_directory_path() /
            ("scout_sim_test_" + std::to_string(::getpid()) + "_" + std::to_string(random()));
    std::filesystem::create_directories(path_);
  }
  ~TempDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

geometry::Box2d Box(double x0, double y0, double x1, double y1) {
  return geometry::Box2d(Eigen::Vector2d(x0, y0), Eigen::Vector2d(x1, y1));
}

// 4 m x 2 m at 0.1 m, unknown outside two free rooms: a 1.0 x 1.0 m one on the
// left and a larger 1.6 x 1.2 m one on the right, with walls around both.
grid::OccupancyMap MakeTwoRoomMap() {
  grid::OccupancyMap map = MakeFilledMap(Box(0, 0, 4, 2), 0.1, grid::CellState::kUnknown);
  FillBox(Box(0.2, 0.2, 1.4, 1.4), grid::CellState::kOccupied, &map);
  FillBox(Box(0.3, 0.3, 1.3, 1.3), grid::CellState::kFree, &map);
  FillBox(Box(2.0, 0.2, 3.8, 1.6), grid::CellState::kOccupied, &map);
  FillBox(Box(2.1, 0.3, 3.7, 1.5), grid::CellState::kFree, &map);
  return map;
}

TEST(Clearance, MeasuresDistanceToNearestNonFreeCell) {
  const grid::OccupancyMap map = MakeTwoRoomMap();
  const std::vector<float> clearance = ComputeClearance(map);
  const auto at = [&](double x, double y) {
    return clearance[map.limits.FlatIndex(map.limits.CellContaining(Eigen::Vector2d(x, y)))];
  };
  EXPECT_FLOAT_EQ(at(0.35, 0.35), 0.1f);
  EXPECT_FLOAT_EQ(at(0.45, 0.75), 0.2f);
  EXPECT_FLOAT_EQ(at(0.05, 0.05), 0.0f);
}

TEST(Clearance, TreatsOutsideOfMapAsNotFree) {
  const grid::OccupancyMap map = MakeFilledMap(Box(0, 0, 1, 1), 0.1, grid::CellState::kFree);
  const std::vector<float> clearance = ComputeClearance(map);
  EXPECT_FLOAT_EQ(clearance[0], 0.1f);
  EXPECT_FLOAT_EQ(clearance[map.limits.FlatIndex({4, 4})], 0.5f);
}

TEST(LoadMapWorld, StartsAtLargestClearanceOfLargestComponent) {
  const TempDirectory dir;
  const std::filesystem::path yaml = dir.path() / "two_rooms.yaml";
  grid::WriteMapServerMap(MakeTwoRoomMap(), yaml);
  const World world = LoadMapWorld(yaml);
  EXPECT_EQ(world.name, "two_rooms");
  EXPECT_EQ(world.map.limits.width(), 40);
  // The right room's cells with the largest clearance (0.6 m) are in its middle row.
  EXPECT_NEAR(world.start.y(), 0.85, 1e-6);
  EXPECT_GE(world.start.x(), 2.6);
  EXPECT_LE(world.start.x(), 3.2);
  EXPECT_EQ(world.map.at(world.map.limits.CellContaining(world.start)), grid::CellState::kFree);
}

TEST(LoadMapWorld, NamesMapSaverDefaultFileAfterItsDirectory) {
  const TempDirectory dir;
  std::filesystem::create_directory(dir.path() / "lab-c069");
  const std::filesystem::path yaml = dir.path() / "lab-c069" / "map.yaml";
  grid::WriteMapServerMap(MakeTwoRoomMap(), yaml);
  EXPECT_EQ(LoadMapWorld(yaml).name, "lab-c069");
  EXPECT_EQ(MapWorldName("floors/building_31.yaml"), "building_31");
  EXPECT_EQ(MapWorldName("/maps/willow/map.yaml"), "willow");
}

TEST(LoadMapWorld, MapWithoutFreeCellIsAnInputError) {
  const TempDirectory dir;
  const std::filesystem::path yaml = dir.path() / "solid.yaml";
  grid::WriteMapServerMap(MakeFilledMap(Box(0, 0, 1, 1), 0.1, grid::CellState::kOccupied), yaml);
  EXPECT_THROW(LoadMapWorld(yaml), InputError);
}

TEST(MakeWorld, BuildsNamedWorldsAndLoadsYaml) {
  EXPECT_EQ(MakeWorld("office", 1).name, "office");
  const TempDirectory dir;
  const std::filesystem::path yaml = dir.path() / "rooms.yaml";
  grid::WriteMapServerMap(MakeTwoRoomMap(), yaml);
  EXPECT_EQ(MakeWorld(yaml.string(), 1).name, "rooms");
}

TEST(MakeWorld, UnknownNameIsAnInputError) {
  try {
    MakeWorld("castle", 1);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "unknown world 'castle': expected office, museum or a map_server .yaml file");
  }
  EXPECT_THROW(MakeWorld("/no/such/map.yaml", 1), InputError);
}

TEST(MakeWorld, SizeScalesGeneratedWorlds) {
  for (const char* name : {"office", "museum"}) {
    const World w = MakeWorld(name, 1, WorldSize{60.0, 45.0});
    // The map covers the building, walls included (to within a cell or two).
    EXPECT_NEAR(w.map.limits.width() * w.map.limits.resolution(), 60.0, 0.2) << name;
    EXPECT_NEAR(w.map.limits.height() * w.map.limits.resolution(), 45.0, 0.2) << name;
  }
}

TEST(MakeWorld, SizeTooSmallNamesTheOption) {
  try {
    MakeWorld("museum", 1, WorldSize{5.0, 100.0});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("width_m"), std::string::npos) << e.what();
  }
  try {
    MakeWorld("office", 1, WorldSize{40.0, 4.0});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("height_m"), std::string::npos) << e.what();
  }
}

TEST(MakeWorld, SizeOfAMapFileIsAnInputError) {
  const TempDirectory dir;
  const std::filesystem::path yaml = dir.path() / "rooms.yaml";
  grid::WriteMapServerMap(MakeTwoRoomMap(), yaml);
  EXPECT_THROW(MakeWorld(yaml.string(), 1, WorldSize{50.0, 50.0}), InputError);
}

TEST(ParseWorldSize, SidesUpToTheLimitAreAccepted) {
  EXPECT_DOUBLE_EQ(ParseWorldSize("500x20").width_m, kMaxWorldSide_m);
  try {
    ParseWorldSize("1000");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("at most 500 m"), std::string::npos) << e.what();
  }
}

TEST(ParseWorldSize, SquareAndRectangle) {
  const WorldSize square = ParseWorldSize("100");
  EXPECT_DOUBLE_EQ(square.width_m, 100.0);
  EXPECT_DOUBLE_EQ(square.height_m, 100.0);
  const WorldSize rect = ParseWorldSize("160x100.5");
  EXPECT_DOUBLE_EQ(rect.width_m, 160.0);
  EXPECT_DOUBLE_EQ(rect.height_m, 100.5);
}

TEST(ParseWorldSize, MalformedIsAnInputError) {
  for (const char* bad : {"", "x", "0", "-5", "10x", "x10", "10x0", "10y10", "nan", "inf", "1e400",
                          "10x10x10", "1e9", "50x1001"}) {
    EXPECT_THROW(ParseWorldSize(bad), InputError) << bad;
  }
}

}  // namespace
}  // namespace scout::sim
