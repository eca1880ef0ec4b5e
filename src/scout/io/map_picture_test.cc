#include "scout/io/map_picture.h"

#include <gtest/gtest.h>

#include <utility>

#include "scout/common/error.h"
#include "scout/grid/image.h"
#include "scout/grid/map_io.h"
#include "scout/grid/submap_fusion.h"
#include "scout/grid/test_temp_directory.h"

namespace scout::io {
namespace {

// An 80 x 48 cell submap at 0.125 m (10 m x 6 m): free for x < 40, an
// occupied wall at x = 40, unknown beyond.
std::shared_ptr<const grid::ProbabilityGrid> HalfKnownSubmap() {
  auto g = std::make_shared<grid::ProbabilityGrid>(grid::MapLimits(0.125, {0, 0}, 80, 48));
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 40; ++x) g->SetProbability({x, y}, 0.2f);
    g->SetProbability({40, y}, 0.9f);
  }
  return g;
}

bool IsColoured(const uint8_t* px) { return px[0] != px[1] || px[1] != px[2]; }

TEST(WriteMapPicture, DrawsTheFusedMapAndTheTrajectoryInColour) {
  const grid::TestTempDirectory dir;
  const GlobalSubmaps submaps = {{geometry::Rigid2d(1.0, 2.0, 0.0), HalfKnownSubmap()}};
  // From (2, 3) east to (4, 3), then north to (4, 7): all inside the free half.
  const std::vector<StampedPose> trajectory = {{0.0, geometry::Rigid2d(2.0, 3.0, 0)},
                                               {1.0, geometry::Rigid2d(4.0, 3.0, 0)},
                                               {2.0, geometry::Rigid2d(4.0, 7.0, 0)}};
  const auto path = dir.path() / "map.png";
  WriteMapPicture(submaps, trajectory, path);
  const grid::Image image = grid::ReadImage(path);
  ASSERT_EQ(image.width, 80);
  ASSERT_EQ(image.height, 48);
  ASSERT_EQ(image.channels, 3);
  // Pixel of a global point: map origin (1, 2), 0.125 m cells, rows flipped.
  const auto at = [&](double x, double y) {
    return image.at(static_cast<int>((x - 1.0) / 0.125), 47 - static_cast<int>((y - 2.0) / 0.125));
  };
  EXPECT_EQ(at(1.6, 7.6)[0], 255);  // free, away from the path
  EXPECT_EQ(at(6.06, 5.0)[0], 0);   // the wall
  EXPECT_EQ(at(9.0, 5.0)[0], 205);  // unknown
  EXPECT_FALSE(IsColoured(at(9.0, 5.0)));
  EXPECT_TRUE(IsColoured(at(3.0, 3.06)));  // on the first leg
  EXPECT_TRUE(IsColoured(at(4.06, 5.5)));  // on the second leg
  const uint8_t* start = at(2.06, 3.06);
  EXPECT_GT(start[1], start[0]);  // green start mark
  const uint8_t* end = at(4.06, 6.94);
  EXPECT_GT(end[0], end[1]);  // orange end mark, not the red end of the path
  EXPECT_GT(end[1], 100);
  int coloured = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) coloured += IsColoured(image.at(x, y));
  }
  // The 16 + 32 cells of the legs plus two discs; no stray colour elsewhere.
  EXPECT_GE(coloured, 48);
  EXPECT_LE(coloured, 48 + 2 * 49);
}

TEST(WriteMapPicture, DrawsTheExplorationOverlay) {
  const grid::TestTempDirectory dir;
  const std::shared_ptr<const grid::ProbabilityGrid> submap = HalfKnownSubmap();
  const GlobalSubmaps submaps = {{geometry::Rigid2d(1.0, 2.0, 0.0), submap}};
  // The picture's map origin is (1, 2), 0.125 m cells, rows flipped.
  const auto path = dir.path() / "map.png";
  MapOverlay overlay;
  // Only the lower half (y < 5) of the submap is highlighted: a second copy
  // of it, 3 m lower, whose upper half overlaps the picture's lower half.
  overlay.highlighted_submaps = {{geometry::Rigid2d(1.0, -1.0, 0.0), submap}};
  overlay.frontier = {{6.25, 7.0}};
  overlay.navigation_points = {{2.5, 6.5}};
  overlay.candidates = {{3.5, 7.2}};
  // A boundary whose west edge runs along x = 1.5 inside the picture and
  // whose other vertices lie a thousand kilometres away (clipped, not walked).
  overlay.boundary = {{1.5, -1e6}, {1e6, -1e6}, {1e6, 1e6}, {1.5, 1e6}};
  WriteMapPicture(submaps, {}, overlay, path);
  const grid::Image image = grid::ReadImage(path);
  ASSERT_EQ(image.width, 80);
  const auto at = [&](double x, double y) {
    return image.at(static_cast<int>((x - 1.0) / 0.125), 47 - static_cast<int>((y - 2.0) / 0.125));
  };
  const uint8_t* tinted = at(3.0, 4.0);
  EXPECT_EQ(tinted[0], 255);
  EXPECT_LT(tinted[1], 255);  // red tint over free space
  const uint8_t* plain = at(2.2, 5.6);
  EXPECT_EQ(plain[1], 255);         // above the highlighted copy: white
  EXPECT_EQ(at(6.06, 4.0)[0], 0);   // walls stay black under the tint
  EXPECT_GT(at(6.3, 7.0)[2], 200);  // frontier: blue
  EXPECT_LT(at(6.3, 7.0)[0], 100);
  EXPECT_GT(at(2.5, 6.5)[1], at(2.5, 6.5)[0]);  // navigation point: green
  const uint8_t* edge = at(1.5, 6.0);           // the boundary: orange
  EXPECT_GT(edge[0], 200);
  EXPECT_GT(edge[1], 80);
  EXPECT_LT(edge[2], 50);
  EXPECT_EQ(at(2.0, 6.0)[2], 255);  // beside it: white
  const uint8_t* candidate = at(3.5, 7.2);
  EXPECT_GT(candidate[0], 150);  // magenta
  EXPECT_GT(candidate[2], 150);
  EXPECT_LT(candidate[1], 50);
  // Without an overlay the same map has no colour at all (checked below).
  // A blacklisted goal on the wall (cell 40, 32): a dark red cross of arms 3
  // cells long, outlined in white over the unknown grey beside the wall.
  overlay = MapOverlay{};
  overlay.blacklisted_goals = {{6.06, 6.06}};
  WriteMapPicture(submaps, {}, overlay, path);
  const grid::Image crossed = grid::ReadImage(path);
  const auto cell = [&](int x, int y) { return crossed.at(x, 47 - y); };
  for (const auto& [x, y] : {std::pair{40, 32}, {42, 34}, {43, 29}, {37, 35}}) {
    EXPECT_EQ(cell(x, y)[0], 150) << x << "," << y;
    EXPECT_EQ(cell(x, y)[1], 0) << x << "," << y;
  }
  EXPECT_EQ(cell(41, 32)[0], 255);  // the outline between the arms
  EXPECT_EQ(cell(41, 32)[2], 255);
  EXPECT_EQ(cell(45, 32)[0], 205);  // beyond the cross: unknown
  EXPECT_EQ(cell(40, 20)[0], 0);    // the wall away from it
  // Without an overlay the same map has no colour at all.
  WriteMapPicture(submaps, {}, path);
  const grid::Image bare = grid::ReadImage(path);
  for (int y = 0; y < bare.height; ++y) {
    for (int x = 0; x < bare.width; ++x) ASSERT_FALSE(IsColoured(bare.at(x, y)));
  }
}

TEST(WriteMapPicture, CoarsensToMaxSideAndCoversTheTrajectory) {
  const grid::TestTempDirectory dir;
  const GlobalSubmaps submaps = {{geometry::Rigid2d(0.0, 0.0, 0.0), HalfKnownSubmap()}};
  // The trajectory leaves the map to x = 20: the picture grows to show it.
  const std::vector<StampedPose> trajectory = {{0.0, geometry::Rigid2d(1.0, 1.0, 0)},
                                               {1.0, geometry::Rigid2d(20.0, 1.0, 0)}};
  const auto path = dir.path() / "small.png";
  WriteMapPicture(submaps, trajectory, path, 50);
  const grid::Image image = grid::ReadImage(path);
  EXPECT_LE(image.width, 50);
  EXPECT_GE(image.width, 49);
  EXPECT_LE(image.height, 16);  // 6 m at 20 m / 49 px
  EXPECT_TRUE(IsColoured(image.at(image.width - 2, image.height - 3)));
  EXPECT_THROW(WriteMapPicture(submaps, trajectory, path, 1), std::invalid_argument);
}

// A 40 x 20 cell world at 0.1 m: a wall at column 20, free elsewhere; the
// left half reachable, its top-left 5 x 5 cells not mapped.
struct CoverageScene {
  grid::OccupancyMap world;
  std::vector<uint8_t> mask;
  CoverageScene() {
    world.limits = grid::MapLimits(0.1, {0.0, 0.0}, 40, 20);
    world.cells.assign(world.limits.num_cells(), grid::CellState::kFree);
    mask.assign(world.limits.num_cells(), 0);
    for (int y = 0; y < 20; ++y) {
      world.set({20, y}, grid::CellState::kOccupied);
      for (int x = 0; x < 20; ++x) mask[world.limits.FlatIndex({x, y})] = x < 5 && y >= 15 ? 1 : 2;
    }
  }
};

TEST(WriteCoveragePicture, ShowsMappedAndUnmappedReachableCells) {
  const grid::TestTempDirectory dir;
  const CoverageScene scene;
  const auto path = dir.path() / "coverage.png";
  WriteCoveragePicture(scene.world, scene.mask, {}, path);
  const grid::Image image = grid::ReadImage(path);
  ASSERT_EQ(image.width, 40);
  ASSERT_EQ(image.height, 20);
  // Rows flipped: world row y is image row 19 - y.
  const auto at = [&](int x, int y) { return image.at(x, 19 - y); };
  EXPECT_TRUE(IsColoured(at(2, 17)));  // unmapped: magenta
  EXPECT_GT(at(2, 17)[2], at(2, 17)[1]);
  EXPECT_EQ(at(10, 5)[0], 255);  // mapped: white
  EXPECT_FALSE(IsColoured(at(10, 5)));
  EXPECT_EQ(at(20, 5)[0], 0);    // the wall
  EXPECT_EQ(at(30, 5)[0], 228);  // free but not reachable
}

TEST(WriteCoveragePicture, CoarseBlocksKeepUnmappedCellsVisible) {
  const grid::TestTempDirectory dir;
  CoverageScene scene;
  // One unmapped cell alone in a mapped area.
  scene.mask[scene.world.limits.FlatIndex({12, 3})] = 1;
  const auto path = dir.path() / "small.png";
  WriteCoveragePicture(scene.world, scene.mask, {}, path, 10);
  const grid::Image image = grid::ReadImage(path);
  EXPECT_EQ(image.width, 10);  // blocks of 4 x 4 cells
  EXPECT_EQ(image.height, 5);
  EXPECT_TRUE(IsColoured(image.at(12 / 4, 4 - 3 / 4)));
  EXPECT_FALSE(IsColoured(image.at(2, 2)));
  EXPECT_THROW(WriteCoveragePicture(scene.world, {1, 2}, {}, path), std::invalid_argument);
}

TEST(WriteMapServerMap, WritesTheFusedMapAtSubmapResolution) {
  const grid::TestTempDirectory dir;
  const GlobalSubmaps submaps = {{geometry::Rigid2d(1.0, 2.0, 0.0), HalfKnownSubmap()},
                                 {geometry::Rigid2d(6.0, 2.0, 0.0), HalfKnownSubmap()}};
  const auto yaml = dir.path() / "map.yaml";
  WriteMapServerMap(submaps, yaml);
  const grid::OccupancyMap read = grid::ReadMapServerMap(yaml);
  const grid::OccupancyMap fused = grid::FuseSubmaps(
      {{submaps[0].second.get(), submaps[0].first}, {submaps[1].second.get(), submaps[1].first}},
      0.125);
  EXPECT_EQ(read.limits.width(), fused.limits.width());
  EXPECT_EQ(read.limits.height(), fused.limits.height());
  EXPECT_NEAR(read.limits.origin().x(), 1.0, 1e-9);
  EXPECT_TRUE(read.cells == fused.cells);
  // Nothing mapped yet: one unknown cell, so that a run stopped before its
  // first scan still writes every output.
  WriteMapServerMap({}, dir.path() / "empty.yaml");
  const grid::OccupancyMap empty = grid::ReadMapServerMap(dir.path() / "empty.yaml");
  ASSERT_EQ(empty.limits.num_cells(), 1);
  EXPECT_EQ(empty.cells[0], grid::CellState::kUnknown);
}

// Two submaps 40 km apart (a SLAM that diverged): at 0.125 m the map would
// have 1e11 cells. It is written at the submap resolution doubled until it
// has at most kMaxGlobalMapCells, and still shows where the submaps lie.
TEST(WriteMapServerMap, SubmapsFarApartAreWrittenCoarser) {
  const grid::TestTempDirectory dir;
  const GlobalSubmaps submaps = {{geometry::Rigid2d(1.0, 2.0, 0.0), HalfKnownSubmap()},
                                 {geometry::Rigid2d(39990.0, -39995.0, 0.0), HalfKnownSubmap()}};
  const double resolution = GlobalMapResolution(submaps);
  // 4 m: 10000 x 10001 cells; 2 m: 20000 x 20002, beyond 2^28.
  EXPECT_DOUBLE_EQ(resolution, 0.125 * 32);
  const auto yaml = dir.path() / "map.yaml";
  WriteMapServerMap(submaps, yaml);
  const grid::OccupancyMap read = grid::ReadMapServerMap(yaml);
  EXPECT_DOUBLE_EQ(read.limits.resolution(), resolution);
  EXPECT_LE(read.limits.num_cells(), kMaxGlobalMapCells);
  // The 4 m cell [39992, 39996) x [-39992, -39988) has its centre 4 m and 5 m
  // into the far submap, in its free half.
  EXPECT_EQ(read.at(read.limits.CellContaining({39993.0, -39991.0})), grid::CellState::kFree);
  // One submap alone keeps its resolution.
  EXPECT_EQ(GlobalMapResolution({submaps[0]}), 0.125);
}

}  // namespace
}  // namespace scout::io
