#include "scout/grid/submap_fusion.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "scout/geometry/box.h"
#include "scout/grid/fusion_test_poses.h"

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

// A 1 m and a 200 m submap 60 km apart, as a diverged SLAM places them:
// 3.6e11 cells at 0.1 m. The fusion refuses by name instead of allocating; a
// coarser resolution found by ResolutionWithin fuses them.
TEST(FuseSubmaps, SubmapsFarApartAreRefusedOrFusedCoarser) {
  const ProbabilityGrid a = Uniform(10, 0.2f);
  const ProbabilityGrid b = Uniform(2000, 0.6f);
  const std::vector<PlacedGrid> placed = {{&a, geometry::Rigid2d()},
                                          {&b, geometry::Rigid2d(60000.0, 60000.0, 0.0)}};
  try {
    FuseSubmaps(placed, 0.1);
    FAIL() << "expected std::length_error";
  } catch (const std::length_error& e) {
    EXPECT_NE(std::string(e.what()).find("has SLAM diverged?"), std::string::npos) << e.what();
  }
  const int64_t max_cells = int64_t{1} << 20;
  const double r = ResolutionWithin(placed, 0.1, max_cells);
  EXPECT_DOUBLE_EQ(r, 0.1 * 1024);  // 60200 m / 102.4 m = 588 cells a side; 51.2 m: 1176
  const OccupancyMap fused = FuseSubmaps(placed, r);
  EXPECT_LE(fused.limits.num_cells(), max_cells);
  EXPECT_EQ(fused.limits.resolution(), r);
  // The cell of (60100, 60100) m has its centre (60057.6, 60057.6) m in b.
  EXPECT_EQ(fused.at(fused.limits.CellContaining({60100, 60100})), CellState::kOccupied);
  // Within the limit the resolution is kept.
  EXPECT_EQ(ResolutionWithin({{&a, geometry::Rigid2d()}}, 0.1, max_cells), 0.1);
  EXPECT_EQ(ResolutionWithin({}, 0.1, max_cells), 0.1);
  EXPECT_THROW(
      ResolutionWithin({{&a, geometry::Rigid2d(std::numeric_limits<double>::infinity(), 0, 0)}},
                       0.1, max_cells),
      std::length_error);
  EXPECT_THROW(ResolutionWithin(placed, 0.0, max_cells), std::invalid_argument);
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

TEST(FuseSubmaps, ACentreOnASubmapCellEdgeTakesTheCellAboveIt) {
  // Half a cell off the lattice in x and y, as a submap is in the world frame
  // of a robot starting at (20.625, 4.575): every centre lies on cell edges.
  ProbabilityGrid g(MapLimits(0.05, {0, 0}, 40, 3));
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 40; ++x) g.SetProbability({x, y}, (x * 7 + y * 3) % 5 < 2 ? 0.8f : 0.2f);
  }
  const OccupancyMap fused = FuseSubmaps({{&g, geometry::Rigid2d(20.625, 4.575, 0)}}, 0.05);
  ASSERT_EQ(fused.limits.width(), 41);
  ASSERT_EQ(fused.limits.height(), 4);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 41; ++x) EXPECT_EQ(fused.at({x, y}), g.State({x, y})) << x << " " << y;
  }
}

TEST(FuseSubmaps, NoSubmapsGiveAnEmptyMap) {
  EXPECT_EQ(FuseSubmaps({}, 0.05).limits.num_cells(), 0);
}

// The plain definition: every cell transforms its centre into every submap.
// Cells whose centre lies on a submap cell edge (up to rounding) may go
// either way, so they are marked in 'on_edge'.
OccupancyMap DirectFusion(const std::vector<PlacedGrid>& submaps, double resolution_m,
                          std::vector<bool>* on_edge) {
  OccupancyMap fused = FuseSubmaps(submaps, resolution_m);  // for the limits only
  std::vector<float> log_odds(fused.limits.num_cells(), 0.f);
  std::vector<bool> known(fused.limits.num_cells(), false);
  on_edge->assign(fused.limits.num_cells(), false);
  for (const PlacedGrid& s : submaps) {
    const MapLimits& limits = s.grid->limits();
    for (int64_t flat = 0; flat < fused.limits.num_cells(); ++flat) {
      const Eigen::Vector2d p =
          s.global_pose.inverse() * fused.limits.CellCenter(fused.limits.CellOfFlatIndex(flat));
      const Eigen::Vector2d q = (p - limits.origin()) / limits.resolution();
      if (std::abs(q.x() - std::round(q.x())) < 1e-6 ||
          std::abs(q.y() - std::round(q.y())) < 1e-6) {
        (*on_edge)[flat] = true;
      }
      const uint16_t value = s.grid->value(limits.CellContaining(p));
      if (value == kUnknownValue) continue;
      const float probability = ValueToProbability(value);
      log_odds[flat] += std::log(probability / (1.f - probability));
      known[flat] = true;
    }
  }
  for (int64_t flat = 0; flat < fused.limits.num_cells(); ++flat) {
    fused.cells[flat] = !known[flat]         ? CellState::kUnknown
                        : log_odds[flat] < 0 ? CellState::kFree
                        : log_odds[flat] > 0 ? CellState::kOccupied
                                             : CellState::kUnknown;
  }
  return fused;
}

ProbabilityGrid RandomGrid() {
  const double resolution = *rc::gen::element(0.05, 0.1);
  const int width = *rc::gen::inRange(1, 30);
  const int height = *rc::gen::inRange(1, 30);
  ProbabilityGrid g(MapLimits(
      resolution, {*rc::gen::inRange(-40, 40) * 0.037, *rc::gen::inRange(-40, 40) * 0.029}, width,
      height));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (*rc::gen::inRange(0, 4) > 0) g.SetProbability({x, y}, *rc::gen::inRange(12, 89) / 100.f);
    }
  }
  return g;
}

// The fast row-wise evaluation (stepped coordinates, rows narrowed to the
// rotated grid) changes no cell, but for centres on a submap cell edge.
RC_GTEST_PROP(FuseSubmaps, EqualsTheCellByCellDefinition, ()) {
  const double resolution = *rc::gen::element(0.05, 0.1);
  std::vector<ProbabilityGrid> grids;
  const int n = *rc::gen::inRange(1, 5);
  for (int i = 0; i < n; ++i) grids.push_back(RandomGrid());
  std::vector<PlacedGrid> placed;
  for (const ProbabilityGrid& g : grids) placed.push_back({&g, testing::RandomSubmapPose()});
  const OccupancyMap fused = FuseSubmaps(placed, resolution);
  std::vector<bool> on_edge;
  const OccupancyMap direct = DirectFusion(placed, resolution, &on_edge);
  for (size_t i = 0; i < fused.cells.size(); ++i) {
    if (!on_edge[i]) RC_ASSERT(fused.cells[i] == direct.cells[i]);
  }
}

// A far submap that moves the map's min corner leaves every other cell as it
// was: the lattice does not depend on the bounds.
RC_GTEST_PROP(FuseSubmaps, CellsDoNotDependOnTheMapBounds, ()) {
  const ProbabilityGrid grid = RandomGrid();
  const ProbabilityGrid far = RandomGrid();
  const std::vector<PlacedGrid> alone = {{&grid, testing::RandomSubmapPose()}};
  const geometry::Rigid2d far_pose(*rc::gen::inRange(-900, -400) / 97.0,
                                   *rc::gen::inRange(-900, -400) / 89.0, 0.3);
  const OccupancyMap a = FuseSubmaps(alone, 0.05);
  const OccupancyMap b = FuseSubmaps({alone[0], {&far, far_pose}}, 0.05);
  const geometry::Box2d far_box = geometry::TransformBox(far_pose, far.limits().Bounds());
  for (int64_t flat = 0; flat < a.limits.num_cells(); ++flat) {
    const Eigen::Vector2d centre = a.limits.CellCenter(a.limits.CellOfFlatIndex(flat));
    if (far_box.Inflated(0.1).Contains(centre)) continue;
    RC_ASSERT(b.at(b.limits.CellContaining(centre)) == a.cells[flat]);
  }
}

}  // namespace
}  // namespace scout::grid
