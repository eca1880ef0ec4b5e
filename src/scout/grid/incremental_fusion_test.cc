#include "scout/grid/incremental_fusion.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <memory>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "scout/grid/fusion_test_poses.h"
#include "scout/grid/submap_fusion.h"

namespace scout::grid {
namespace {

using GridPtr = std::shared_ptr<const ProbabilityGrid>;

GridPtr SharedUniform(int n, float p) {
  auto g = std::make_shared<ProbabilityGrid>(MapLimits(0.1, {0, 0}, n, n));
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) g->SetProbability({x, y}, p);
  }
  return g;
}

OccupancyMap Reference(const std::vector<FusionInput>& submaps, double resolution_m) {
  std::vector<PlacedGrid> placed;
  for (const FusionInput& s : submaps) placed.push_back({s.grid.get(), s.global_pose});
  return FuseSubmaps(placed, resolution_m);
}

// Same limits (bit for bit) and same cells.
bool SameMap(const OccupancyMap& a, const OccupancyMap& b) {
  return a.limits.resolution() == b.limits.resolution() && a.limits.origin() == b.limits.origin() &&
         a.limits.width() == b.limits.width() && a.limits.height() == b.limits.height() &&
         a.cells == b.cells;
}

TEST(IncrementalSubmapFusion, ReusesFinishedSubmapsUntilAnOptimisationMovesThem) {
  IncrementalSubmapFusion fusion(0.1);
  std::vector<FusionInput> submaps = {
      {0, SharedUniform(10, 0.2f), geometry::Rigid2d(), true},
      {1, SharedUniform(10, 0.6f), geometry::Rigid2d(0.5, 0, 0), true},
      {2, SharedUniform(10, 0.45f), geometry::Rigid2d(1.0, 0, 0), false}};
  const OccupancyMap* map = &fusion.Update(submaps);
  ASSERT_TRUE(SameMap(*map, Reference(submaps, 0.1)));
  ASSERT_EQ(map->limits.width(), 20);
  EXPECT_EQ(map->at({2, 5}), CellState::kFree);       // only submap 0
  EXPECT_EQ(map->at({7, 5}), CellState::kFree);       // logit(0.2) + logit(0.6) < 0
  EXPECT_EQ(map->at({12, 5}), CellState::kOccupied);  // logit(0.6) + logit(0.45) > 0
  EXPECT_EQ(map->at({17, 5}), CellState::kFree);      // only submap 2
  EXPECT_EQ(fusion.statistics().base_additions, 2);
  EXPECT_EQ(fusion.statistics().active_additions, 1);

  // The active submap got a new snapshot: only it is added again.
  submaps[2].grid = SharedUniform(10, 0.9f);
  map = &fusion.Update(submaps);
  ASSERT_TRUE(SameMap(*map, Reference(submaps, 0.1)));
  EXPECT_EQ(map->at({17, 5}), CellState::kOccupied);
  EXPECT_EQ(fusion.statistics().base_additions, 2);
  EXPECT_EQ(fusion.statistics().active_additions, 2);

  // It is finished and a new one grows the map towards -x (a new origin).
  submaps[2].finished = true;
  submaps.push_back({3, SharedUniform(10, 0.3f), geometry::Rigid2d(-1.0, 0, 0), false});
  map = &fusion.Update(submaps);
  ASSERT_TRUE(SameMap(*map, Reference(submaps, 0.1)));
  ASSERT_EQ(map->limits.width(), 30);
  EXPECT_EQ(map->at({12, 5}), CellState::kFree);  // submap 0 alone, moved by 10 columns
  EXPECT_EQ(fusion.statistics().base_additions, 3);
  EXPECT_EQ(fusion.statistics().base_rebuilds, 0);

  // An optimisation moves every pose: the cached sums are rebuilt.
  const geometry::Rigid2d correction(0.03, -0.02, 0.01);
  for (FusionInput& s : submaps) s.global_pose = correction * s.global_pose;
  map = &fusion.Update(submaps);
  ASSERT_TRUE(SameMap(*map, Reference(submaps, 0.1)));
  EXPECT_EQ(fusion.statistics().base_rebuilds, 1);
  EXPECT_EQ(fusion.statistics().base_additions, 6);
}

TEST(IncrementalSubmapFusion, NoSubmapsGiveAnEmptyMapAndBadInputThrows) {
  IncrementalSubmapFusion fusion(0.05);
  EXPECT_EQ(fusion.Update({}).limits.num_cells(), 0);
  EXPECT_THROW(fusion.Update({{0, nullptr, geometry::Rigid2d(), false}}), std::invalid_argument);
  EXPECT_THROW(IncrementalSubmapFusion(0.0), std::invalid_argument);
}

GridPtr SharedRandomGrid() {
  const double resolution = *rc::gen::element(0.05, 0.1);
  const int width = *rc::gen::inRange(1, 30);
  const int height = *rc::gen::inRange(1, 30);
  const Eigen::Vector2d origin(*rc::gen::inRange(-40, 40) * 0.037,
                               *rc::gen::inRange(-40, 40) * 0.029);
  auto g = std::make_shared<ProbabilityGrid>(MapLimits(resolution, origin, width, height));
  const int percent_known = *rc::gen::inRange(0, 101);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (*rc::gen::inRange(0, 100) >= percent_known) continue;
      g->SetProbability({x, y}, *rc::gen::inRange(12, 89) / 100.f);
    }
  }
  return g;
}

// What the exploration loop does between fusions, in any order: new submaps,
// new snapshots of active ones, finishing, and optimisations moving all.
RC_GTEST_PROP(IncrementalSubmapFusion, EveryUpdateEqualsFuseSubmaps, ()) {
  const double resolution = *rc::gen::element(0.05, 0.1);
  IncrementalSubmapFusion fusion(resolution);
  std::vector<FusionInput> submaps;
  const int steps = *rc::gen::inRange(1, 30);
  for (int step = 0; step < steps; ++step) {
    std::vector<size_t> active;
    for (size_t i = 0; i < submaps.size(); ++i) {
      if (!submaps[i].finished) active.push_back(i);
    }
    switch (*rc::gen::inRange(0, 5)) {
      case 0:
        submaps.push_back({static_cast<int>(submaps.size()), SharedRandomGrid(),
                           testing::RandomSubmapPose(), false});
        break;
      case 1:
        if (!active.empty()) submaps[*rc::gen::elementOf(active)].grid = SharedRandomGrid();
        break;
      case 2:
        if (!active.empty()) submaps[*rc::gen::elementOf(active)].finished = true;
        break;
      case 3: {
        const geometry::Rigid2d correction(*rc::gen::inRange(-20, 21) / 100.0,
                                           *rc::gen::inRange(-20, 21) / 100.0,
                                           *rc::gen::inRange(-10, 11) / 100.0);
        for (FusionInput& s : submaps) s.global_pose = correction * s.global_pose;
        break;
      }
      default:
        break;  // fused again unchanged
    }
    RC_ASSERT(SameMap(fusion.Update(submaps), Reference(submaps, resolution)));
  }
}

}  // namespace
}  // namespace scout::grid
