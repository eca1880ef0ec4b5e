#include "scout/grid/range_data_inserter.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace scout::grid {
namespace {

const RangeDataInserterOptions kOptions;  // hit 0.55, miss 0.49
// What one hit / one miss leaves in an unknown cell (stored values are quantised).
const float kOneHit = ValueToProbability(ProbabilityToValue(0.55f));
const float kOneMiss = ValueToProbability(ProbabilityToValue(0.49f));

ProbabilityGrid MakeGrid() { return ProbabilityGrid(MapLimits(0.05, {0, 0}, 100, 100)); }

// Returns true if the segment a-b meets the open interior of 'cell' (Liang-Barsky
// clipping against the cell's box shrunk by a hair, so mere corner or edge
// contact does not count).
bool SegmentCrossesCell(const MapLimits& limits, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                        const CellIndex& cell, double shrink) {
  const Eigen::Vector2d lo = limits.origin() +
                             limits.resolution() * Eigen::Vector2d(cell.x, cell.y) +
                             Eigen::Vector2d::Constant(shrink);
  const Eigen::Vector2d hi = lo + Eigen::Vector2d::Constant(limits.resolution() - 2 * shrink);
  double t0 = 0.0, t1 = 1.0;
  const Eigen::Vector2d d = b - a;
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0.0) {
      if (a[axis] < lo[axis] || a[axis] > hi[axis]) return false;
      continue;
    }
    double ta = (lo[axis] - a[axis]) / d[axis], tb = (hi[axis] - a[axis]) / d[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

TEST(RangeDataInserter, RayMarksCrossedCellsFreeAndEndOccupied) {
  ProbabilityGrid grid = MakeGrid();
  const RangeDataInserter inserter(kOptions);
  // From the centre of cell (10, 10) to the centre of cell (20, 10).
  inserter.Insert({0.525, 0.525}, {{1.025, 0.525}}, {}, &grid);
  for (int x = 10; x < 20; ++x) {
    EXPECT_EQ(grid.State({x, 10}), CellState::kFree) << x;
    EXPECT_EQ(grid.GetProbability({x, 10}), kOneMiss);
  }
  EXPECT_EQ(grid.State({20, 10}), CellState::kOccupied);
  EXPECT_EQ(grid.GetProbability({20, 10}), kOneHit);
  EXPECT_FALSE(grid.IsKnown({21, 10}));
  EXPECT_FALSE(grid.IsKnown({15, 11}));
  EXPECT_FALSE(grid.IsKnown({9, 10}));
  for (const uint16_t raw : grid.values()) ASSERT_FALSE(raw & kUpdateMarker);
}

TEST(RangeDataInserter, HitsWinOverMissesInTheSameScan) {
  ProbabilityGrid grid = MakeGrid();
  const RangeDataInserter inserter(kOptions);
  // The second ray passes through the first return's cell.
  inserter.Insert({0.525, 0.525}, {{0.775, 0.525}, {1.025, 0.525}}, {}, &grid);
  EXPECT_EQ(grid.GetProbability({15, 10}), kOneHit);
  EXPECT_EQ(grid.State({15, 10}), CellState::kOccupied);
  EXPECT_EQ(grid.State({16, 10}), CellState::kFree);
}

TEST(RangeDataInserter, EachCellIsUpdatedOncePerScan) {
  ProbabilityGrid grid = MakeGrid();
  const RangeDataInserter inserter(kOptions);
  // Three rays share the cells next to the origin.
  inserter.Insert({0.525, 0.525}, {{1.525, 0.525}, {1.525, 0.55}, {1.525, 0.5}}, {}, &grid);
  EXPECT_EQ(grid.GetProbability({10, 10}), kOneMiss);
  EXPECT_EQ(grid.GetProbability({12, 10}), kOneMiss);
}

TEST(RangeDataInserter, RepeatedScansConvergeToTheClamps) {
  ProbabilityGrid grid = MakeGrid();
  const RangeDataInserter inserter(kOptions);
  float previous_hit = 0.5f, previous_miss = 0.5f;
  for (int i = 0; i < 400; ++i) {
    inserter.Insert({0.525, 0.525}, {{1.025, 0.525}}, {}, &grid);
    const float hit = grid.GetProbability({20, 10});
    const float miss = grid.GetProbability({12, 10});
    ASSERT_GE(hit, previous_hit);
    ASSERT_LE(miss, previous_miss);
    previous_hit = hit;
    previous_miss = miss;
  }
  EXPECT_EQ(grid.GetProbability({20, 10}), kMaxProbability);
  EXPECT_EQ(grid.GetProbability({12, 10}), kMinProbability);
}

TEST(RangeDataInserter, MissesMarkTheEndCellFree) {
  ProbabilityGrid grid = MakeGrid();
  const RangeDataInserter inserter(kOptions);
  inserter.Insert({0.525, 0.525}, {}, {{0.525, 1.025}}, &grid);
  for (int y = 10; y <= 20; ++y) EXPECT_EQ(grid.State({10, y}), CellState::kFree) << y;
  EXPECT_FALSE(grid.IsKnown({10, 21}));
}

TEST(RangeDataInserter, ReturnInTheOriginCellIsOnlyAHit) {
  ProbabilityGrid grid = MakeGrid();
  const RangeDataInserter inserter(kOptions);
  inserter.Insert({0.51, 0.51}, {{0.54, 0.52}}, {}, &grid);
  EXPECT_EQ(grid.State({10, 10}), CellState::kOccupied);
  int known = 0;
  for (const uint16_t raw : grid.values()) known += raw != kUnknownValue;
  EXPECT_EQ(known, 1);
}

TEST(RangeDataInserter, GrowsTheGridToContainEveryPoint) {
  ProbabilityGrid grid;  // empty
  const RangeDataInserter inserter(kOptions);
  inserter.Insert({0.0, 0.0}, {{3.0, -2.0}}, {{-4.0, 5.0}}, &grid);
  const MapLimits& limits = grid.limits();
  for (const Eigen::Vector2d& p :
       {Eigen::Vector2d(0, 0), Eigen::Vector2d(3, -2), Eigen::Vector2d(-4, 5)}) {
    EXPECT_TRUE(limits.Contains(limits.CellContaining(p)));
  }
  EXPECT_EQ(grid.State(limits.CellContaining({3.0, -2.0})), CellState::kOccupied);
  EXPECT_EQ(grid.State(limits.CellContaining({-4.0, 5.0})), CellState::kFree);
  EXPECT_EQ(grid.State(limits.CellContaining({1.5, -1.0})), CellState::kFree);
}

TEST(RangeDataInserter, RejectsBadOptionsAndInput) {
  EXPECT_THROW(RangeDataInserter({0.5, 0.49}), std::invalid_argument);
  EXPECT_THROW(RangeDataInserter({1.0, 0.49}), std::invalid_argument);
  EXPECT_THROW(RangeDataInserter({0.55, 0.5}), std::invalid_argument);
  EXPECT_THROW(RangeDataInserter({0.55, 0.0}), std::invalid_argument);
  const RangeDataInserter inserter(kOptions);
  EXPECT_THROW(inserter.Insert({0, 0}, {{1, 1}}, {}, nullptr), std::invalid_argument);
  ProbabilityGrid grid = MakeGrid();
  EXPECT_THROW(inserter.Insert({0, 0}, {{std::nan(""), 1}}, {}, &grid), std::invalid_argument);
}

// Exactness of the traversal: every cell whose interior a ray crosses is
// updated, and nothing is updated that the ray does not at least touch.
RC_GTEST_PROP(RangeDataInserter, RayUpdatesExactlyTheCellsItCrosses, ()) {
  ProbabilityGrid grid(MapLimits(0.05, {-0.013, 0.021}, 60, 60));
  const auto coordinate = [] { return *rc::gen::inRange(0, 2800) * 0.001 + 0.1; };
  // Some rays start and end on cell borders (multiples of the resolution away
  // from the origin) to exercise ties.
  const bool on_grid = *rc::gen::arbitrary<bool>();
  const auto snap = [&](double v, double grid_origin) {
    return on_grid ? grid_origin + std::round((v - grid_origin) / 0.05) * 0.05 : v;
  };
  const Eigen::Vector2d origin(snap(coordinate(), -0.013), snap(coordinate(), 0.021));
  const Eigen::Vector2d end(snap(coordinate(), -0.013), snap(coordinate(), 0.021));
  const bool as_miss = *rc::gen::arbitrary<bool>();
  const RangeDataInserter inserter(kOptions);
  if (as_miss) {
    inserter.Insert(origin, {}, {end}, &grid);
  } else {
    inserter.Insert(origin, {end}, {}, &grid);
  }
  const MapLimits& limits = grid.limits();
  const CellIndex end_cell = limits.CellContaining(end);
  for (int64_t i = 0; i < limits.num_cells(); ++i) {
    const CellIndex cell = limits.CellOfFlatIndex(i);
    if (cell == end_cell) {
      RC_ASSERT(grid.State(cell) == (as_miss ? CellState::kFree : CellState::kOccupied));
      continue;
    }
    if (SegmentCrossesCell(limits, origin, end, cell, 1e-9)) {
      RC_ASSERT(grid.State(cell) == CellState::kFree);
    } else if (!SegmentCrossesCell(limits, origin, end, cell, -1e-9)) {
      RC_ASSERT(!grid.IsKnown(cell));
    }
  }
}

}  // namespace
}  // namespace scout::grid
