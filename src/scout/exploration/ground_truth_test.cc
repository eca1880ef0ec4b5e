#include "scout/exploration/ground_truth.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "scout/common/error.h"
#include "scout/exploration/test_worlds.h"

namespace scout::exploration {
namespace {

using grid::CellState;

GroundTruth Truth(const sim::World& w) { return GroundTruth(w.map, w.name, w.start, {}, 0.20); }

TEST(GroundTruthTest, ReachableAreaIsWhatTheDiscCoversAwayFromTheInflationBand) {
  const sim::World w = testing::SmallBuilding();
  const GroundTruth truth = Truth(w);
  // The rooms hold 9 x 6 m minus the wall, pillar and closet; the disc keeps
  // 0.40 m between its centre and walls, so it covers all but a 0.2 m band.
  EXPECT_GT(truth.reachable_free_m2(), 35.0);
  EXPECT_LT(truth.reachable_free_m2(), 48.0);
  const std::vector<uint8_t> mask = truth.ReachableMask();
  const grid::MapLimits& l = w.map.limits;
  EXPECT_EQ(truth.limits().num_cells(), l.num_cells());
  EXPECT_TRUE(mask[l.FlatIndex(l.CellContaining({6.5, 1.5}))]);   // the right room
  EXPECT_FALSE(mask[l.FlatIndex(l.CellContaining({8.6, 5.6}))]);  // inside the closet
  EXPECT_FALSE(mask[l.FlatIndex(l.CellContaining({0.2, 3.0}))]);  // against the left wall
}

TEST(GroundTruthTest, MappedAreaCountsOnlyFreeCellsWhereTheWorldIsFree) {
  const sim::World w = testing::SmallBuilding();
  const GroundTruth truth = Truth(w);
  EXPECT_DOUBLE_EQ(truth.MappedFreeM2(w.map, geometry::Rigid2d()), truth.reachable_free_m2());

  grid::OccupancyMap unknown = w.map;
  std::fill(unknown.cells.begin(), unknown.cells.end(), CellState::kUnknown);
  EXPECT_EQ(truth.MappedFreeM2(unknown, geometry::Rigid2d()), 0.0);

  // A map in a frame shifted by (1, 0): the same free space, placed back by
  // world_from_map, counts in full; without the transform it does not.
  grid::OccupancyMap shifted = w.map;
  shifted.limits = grid::MapLimits(0.05, {-1.0, 0.0}, w.map.limits.width(), w.map.limits.height());
  EXPECT_DOUBLE_EQ(truth.MappedFreeM2(shifted, geometry::Rigid2d(1.0, 0.0, 0.0)),
                   truth.reachable_free_m2());
  EXPECT_LT(truth.MappedFreeM2(shifted, geometry::Rigid2d()), 0.95 * truth.reachable_free_m2());

  // Only the left room mapped: about half.
  grid::OccupancyMap left = unknown;
  testing::Paint(left, 0.15, 0.15, 4.45, 6.15, CellState::kFree);
  const double share = truth.MappedFreeM2(left, geometry::Rigid2d()) / truth.reachable_free_m2();
  EXPECT_GT(share, 0.4);
  EXPECT_LT(share, 0.6);
}

// A map that covers only part of the world, turned and shifted: MappedFreeM2
// counts exactly the reachable cells whose centres the transform puts on a
// free map cell (most of the world lies beyond this map, and is skipped).
TEST(GroundTruthTest, APartialMapCountsTheCellsItCovers) {
  const sim::World w = testing::SmallBuilding();
  const GroundTruth truth = Truth(w);
  grid::OccupancyMap part;
  part.limits = grid::MapLimits(0.05, {1.013, 0.527}, 61, 47);
  part.cells.assign(static_cast<size_t>(part.limits.num_cells()), CellState::kFree);
  for (const geometry::Rigid2d& world_from_map :
       {geometry::Rigid2d(0.0123, -0.0371, 0.05), geometry::Rigid2d(3.1, 2.2, -0.7),
        geometry::Rigid2d(6.0, 4.0, 2.9)}) {
    const geometry::Rigid2d map_from_world = world_from_map.inverse();
    const std::vector<uint8_t> reachable = truth.ReachableMask();
    int64_t expected = 0;
    for (int64_t i = 0; i < truth.limits().num_cells(); ++i) {
      if (!reachable[i]) continue;
      const Eigen::Vector2d p =
          map_from_world * truth.limits().CellCenter(truth.limits().CellOfFlatIndex(i));
      expected += part.limits.Contains(part.limits.CellContaining(p));
    }
    EXPECT_GT(expected, 0);
    EXPECT_DOUBLE_EQ(truth.MappedFreeM2(part, world_from_map), expected * 0.05 * 0.05);
  }
}

// The mask says cell by cell what MappedFreeM2 counts.
TEST(GroundTruthTest, CoverageMaskMarksTheReachableCellsMappedOrNot) {
  const sim::World w = testing::SmallBuilding();
  const GroundTruth truth = Truth(w);
  grid::OccupancyMap left = w.map;
  std::fill(left.cells.begin(), left.cells.end(), CellState::kUnknown);
  testing::Paint(left, 0.15, 0.15, 4.45, 6.15, CellState::kFree);
  const std::vector<uint8_t> mask = truth.CoverageMask(left, geometry::Rigid2d());
  const std::vector<uint8_t> reachable = truth.ReachableMask();
  ASSERT_EQ(mask.size(), reachable.size());
  int64_t mapped = 0;
  for (size_t i = 0; i < mask.size(); ++i) {
    EXPECT_EQ(mask[i] != GroundTruth::kNotReachable, reachable[i] != 0) << i;
    mapped += mask[i] == GroundTruth::kMapped;
  }
  EXPECT_DOUBLE_EQ(mapped * 0.05 * 0.05, truth.MappedFreeM2(left, geometry::Rigid2d()));
  const grid::MapLimits& l = w.map.limits;
  EXPECT_EQ(mask[l.FlatIndex(l.CellContaining({2.0, 3.0}))], GroundTruth::kMapped);
  EXPECT_EQ(mask[l.FlatIndex(l.CellContaining({6.5, 1.5}))], GroundTruth::kUnmapped);
  // An empty map maps nothing.
  const std::vector<uint8_t> none = truth.CoverageMask(grid::OccupancyMap(), geometry::Rigid2d());
  EXPECT_EQ(std::count(none.begin(), none.end(), GroundTruth::kMapped), 0);
  EXPECT_EQ(std::count(none.begin(), none.end(), GroundTruth::kUnmapped),
            std::count(reachable.begin(), reachable.end(), 1));
}

// The row-wise stepping of MappedFreeM2 counts exactly what transforming every
// reachable cell centre on its own counts, for maps of another resolution,
// origin and rotation.
TEST(GroundTruthTest, MappedAreaEqualsACellByCellCountUnderAnyPlacement) {
  const sim::World w = testing::SmallBuilding();
  const GroundTruth truth = Truth(w);
  const std::vector<uint8_t> reachable = truth.ReachableMask();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const double resolution = trial % 2 == 0 ? 0.05 : 0.04;
    grid::OccupancyMap map;
    // Centred on the world (its centre at the map frame's origin), any angle.
    map.limits = grid::MapLimits(resolution, {-6.0 - uniform(rng), -5.0 - uniform(rng)}, 360, 300);
    map.cells.resize(map.limits.num_cells());
    for (CellState& c : map.cells) c = uniform(rng) < 0.7 ? CellState::kFree : CellState::kOccupied;
    const Eigen::Vector2d centre = truth.limits().Bounds().Center();
    const geometry::Rigid2d world_from_map(centre.x() + uniform(rng) - 0.5,
                                           centre.y() + uniform(rng) - 0.5,
                                           2.0 * M_PI * uniform(rng));
    const geometry::Rigid2d map_from_world = world_from_map.inverse();
    int64_t expected = 0;
    const grid::MapLimits& world = truth.limits();
    for (int64_t i = 0; i < world.num_cells(); ++i) {
      if (!reachable[i]) continue;
      const Eigen::Vector2d p = map_from_world * world.CellCenter(world.CellOfFlatIndex(i));
      expected += map.at(map.limits.CellContaining(p)) == CellState::kFree;
    }
    const int64_t num_reachable = std::count(reachable.begin(), reachable.end(), 1);
    ASSERT_GT(expected, num_reachable / 2);  // the map covers the building
    EXPECT_NEAR(truth.MappedFreeM2(map, world_from_map), expected * 0.05 * 0.05, 1e-9) << trial;
  }
}

TEST(GroundTruthTest, BeyondTheMapIsAWallLikeInTheSimulator) {
  // A 4 m x 3 m map that is free up to its border: the disc keeps its radius
  // plus the safety margin (0.40 m) from the border, and covers all but 0.2 m.
  sim::World w;
  w.name = "open";
  w.map.limits = grid::MapLimits(0.05, {0.0, 0.0}, 80, 60);
  w.map.cells.assign(80 * 60, CellState::kFree);
  w.start = {2.0, 1.5};
  const GroundTruth truth = Truth(w);
  EXPECT_NEAR(truth.reachable_free_m2(), (4.0 - 0.4) * (3.0 - 0.4), 0.1);
  EXPECT_FALSE(truth.DiscCanReach({2.0, 1.5}, {0.1, 1.5}, 0.05));  // the disc would leave the map
  EXPECT_TRUE(truth.DiscCanReach({2.0, 1.5}, {0.3, 1.5}, 0.05));
}

TEST(GroundTruthTest, AStartWhoseDiscOverlapsUnknownSpaceIsAnInputErrorNamingStart) {
  // One unknown cell (x 2.00-2.05 m) in a free room: the planning grid
  // inflates only occupied cells, but the simulator's robot collides with
  // unknown ones too. From x = 1.825 the disc (radius 0.2 m) reaches 2.5 cm
  // into it.
  sim::World w;
  w.name = "room";
  w.map.limits = grid::MapLimits(0.05, {0.0, 0.0}, 80, 60);
  w.map.cells.assign(80 * 60, CellState::kFree);
  w.map.cells[w.map.limits.FlatIndex({40, 30})] = CellState::kUnknown;
  w.start = {1.825, 1.525};
  try {
    Truth(w);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("choose a free position with --start X,Y"),
              std::string::npos)
        << e.what();
  }
  w.start = {1.775, 1.525};  // the disc ends 2.5 cm short of the square
  EXPECT_NO_THROW(Truth(w));
}

TEST(GroundTruthTest, TheDiscReachesTheOtherRoomButNotTheCloset) {
  const GroundTruth truth = Truth(testing::SmallBuilding());
  EXPECT_TRUE(truth.DiscCanReach({1.5, 1.5}, {7.0, 2.0}, 0.25));
  EXPECT_TRUE(truth.DiscCanReach({1.5, 1.5}, {8.55, 4.5}, 0.25));    // in front of the gap
  EXPECT_FALSE(truth.DiscCanReach({1.5, 1.5}, {8.55, 5.6}, 0.25));   // behind it
  EXPECT_FALSE(truth.DiscCanReach({1.5, 1.5}, {20.0, 20.0}, 0.25));  // off the map
}

TEST(GroundTruthTest, StartInAWallOrWithoutRoomIsAnInputError) {
  sim::World w = testing::SmallBuilding();
  w.start = {4.55, 1.0};  // inside the dividing wall
  try {
    Truth(w);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--start"), std::string::npos) << e.what();
  }
  // A corridor 0.6 m wide: the bare disc fits, the inflated robot does not.
  sim::World narrow = w;
  std::fill(narrow.map.cells.begin(), narrow.map.cells.end(), CellState::kOccupied);
  testing::Paint(narrow.map, 1.0, 1.0, 1.6, 5.0, CellState::kFree);
  narrow.start = {1.3, 3.0};
  EXPECT_THROW(Truth(narrow), InputError);
}

}  // namespace
}  // namespace scout::exploration
