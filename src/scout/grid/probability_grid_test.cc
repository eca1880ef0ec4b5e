#include "scout/grid/probability_grid.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "scout/grid/cell_state.h"
#include "scout/grid/probability_values.h"

namespace scout::grid {
namespace {

constexpr float kStep = (kMaxProbability - kMinProbability) / (kMaxValue - 1);

TEST(ProbabilityValues, EveryKnownValueRoundTrips) {
  for (int v = 1; v <= kMaxValue; ++v) {
    ASSERT_EQ(ProbabilityToValue(ValueToProbability(static_cast<uint16_t>(v))), v) << v;
  }
}

TEST(ProbabilityValues, EndpointsAndMidpointAreExact) {
  EXPECT_EQ(ValueToProbability(1), kMinProbability);
  EXPECT_EQ(ValueToProbability(kMaxValue), kMaxProbability);
  EXPECT_EQ(ValueToProbability(ProbabilityToValue(0.5f)), 0.5f);
  EXPECT_EQ(ValueToProbability(kUnknownValue), 0.5f);
  // The update marker does not change the probability a value stands for.
  EXPECT_EQ(ValueToProbability(ProbabilityToValue(0.7f) | kUpdateMarker),
            ValueToProbability(ProbabilityToValue(0.7f)));
}

TEST(ProbabilityValues, ClampsToTheKnownRange) {
  EXPECT_EQ(ProbabilityToValue(0.0f), 1);
  EXPECT_EQ(ProbabilityToValue(0.05f), 1);
  EXPECT_EQ(ProbabilityToValue(-3.0f), 1);
  EXPECT_EQ(ProbabilityToValue(1.0f), kMaxValue);
  EXPECT_EQ(ProbabilityToValue(0.95f), kMaxValue);
  EXPECT_EQ(ProbabilityToValue(std::numeric_limits<float>::infinity()), kMaxValue);
  // A probability never encodes as "unknown".
  EXPECT_NE(ProbabilityToValue(std::nanf("")), kUnknownValue);
}

RC_GTEST_PROP(ProbabilityValues, ProbabilityRoundTripsWithinHalfAStep, ()) {
  const float p = kMinProbability + *rc::gen::inRange(0, 1000001) / 1e6f * 0.8f;
  const float back = ValueToProbability(ProbabilityToValue(std::min(p, kMaxProbability)));
  RC_ASSERT(std::abs(back - p) <= 0.5f * kStep + 1e-6f);
}

TEST(ProbabilityValues, LookupTableAppliesOddsOnceAndMarks) {
  const float hit_odds = Odds(0.55f);
  const std::vector<uint16_t> table = ComputeLookupTableToApplyOdds(hit_odds);
  ASSERT_EQ(table.size(), 65536u);
  // An unknown cell takes the observation's probability.
  EXPECT_EQ(table[kUnknownValue], ProbabilityToValue(0.55f) | kUpdateMarker);
  // A known cell multiplies its odds.
  const uint16_t v = ProbabilityToValue(0.6f);
  EXPECT_NEAR(ValueToProbability(table[v]),
              ProbabilityFromOdds(hit_odds * Odds(ValueToProbability(v))), kStep);
  for (int raw = 0; raw <= kMaxValue; ++raw) ASSERT_TRUE(table[raw] & kUpdateMarker);
  // Already-marked inputs are left alone.
  for (int raw = kUpdateMarker; raw < 65536; ++raw) ASSERT_EQ(table[raw], raw);
  EXPECT_THROW(ComputeLookupTableToApplyOdds(0.f), std::invalid_argument);
}

TEST(MapLimits, RejectsInvalidGeometry) {
  const Eigen::Vector2d o(0, 0);
  EXPECT_THROW(MapLimits(0.0, o, 1, 1), std::invalid_argument);
  EXPECT_THROW(MapLimits(-0.05, o, 1, 1), std::invalid_argument);
  EXPECT_THROW(MapLimits(std::nan(""), o, 1, 1), std::invalid_argument);
  EXPECT_THROW(MapLimits(std::numeric_limits<double>::infinity(), o, 1, 1), std::invalid_argument);
  EXPECT_THROW(MapLimits(0.05, o, -1, 1), std::invalid_argument);
  EXPECT_THROW(MapLimits(0.05, o, 1, -1), std::invalid_argument);
  EXPECT_NO_THROW(MapLimits(0.05, o, 0, 0));
}

TEST(CellState, NamesEveryState) {
  EXPECT_EQ(ToString(CellState::kUnknown), "unknown");
  EXPECT_EQ(ToString(CellState::kFree), "free");
  EXPECT_EQ(ToString(CellState::kOccupied), "occupied");
}

TEST(ProbabilityGrid, NewCellsAndOutsideAreUnknown) {
  const ProbabilityGrid grid(MapLimits(0.05, {1.0, -2.0}, 4, 3));
  EXPECT_FALSE(grid.IsKnown({0, 0}));
  EXPECT_EQ(grid.State({3, 2}), CellState::kUnknown);
  EXPECT_EQ(grid.State({-1, 0}), CellState::kUnknown);
  EXPECT_EQ(grid.GetProbability({4, 0}), 0.5f);
  EXPECT_EQ(grid.value({0, 3}), kUnknownValue);
}

TEST(ProbabilityGrid, StateFollowsProbabilityAndHalfIsUnknown) {
  ProbabilityGrid grid(MapLimits(0.05, {0, 0}, 3, 1));
  grid.SetProbability({0, 0}, 0.5f);
  grid.SetProbability({1, 0}, 0.49f);
  grid.SetProbability({2, 0}, 0.51f);
  EXPECT_TRUE(grid.IsKnown({0, 0}));
  EXPECT_EQ(grid.State({0, 0}), CellState::kUnknown);
  EXPECT_EQ(grid.State({1, 0}), CellState::kFree);
  EXPECT_EQ(grid.State({2, 0}), CellState::kOccupied);
  EXPECT_EQ(grid.States(),
            (std::vector<CellState>{CellState::kUnknown, CellState::kFree, CellState::kOccupied}));
  EXPECT_THROW(grid.SetProbability({3, 0}, 0.7f), std::out_of_range);
}

TEST(ProbabilityGrid, LookupTableAppliesAtMostOncePerUpdate) {
  ProbabilityGrid grid(MapLimits(0.05, {0, 0}, 2, 2));
  const std::vector<uint16_t> hit = ComputeLookupTableToApplyOdds(Odds(0.55f));
  EXPECT_TRUE(grid.ApplyLookupTable({1, 1}, hit));
  const uint16_t after_one = grid.value({1, 1});
  EXPECT_EQ(after_one, ProbabilityToValue(0.55f));
  EXPECT_TRUE(grid.values()[grid.limits().FlatIndex({1, 1})] & kUpdateMarker);
  EXPECT_FALSE(grid.ApplyLookupTable({1, 1}, hit));
  EXPECT_EQ(grid.value({1, 1}), after_one);

  grid.FinishUpdate();
  for (const uint16_t raw : grid.values()) EXPECT_FALSE(raw & kUpdateMarker);
  EXPECT_TRUE(grid.ApplyLookupTable({1, 1}, hit));
  EXPECT_GT(grid.GetProbability({1, 1}), ValueToProbability(after_one));
  EXPECT_THROW(grid.ApplyLookupTable({2, 0}, hit), std::out_of_range);
}

TEST(ProbabilityGrid, ApplyReportsNoChangeAtTheClamp) {
  ProbabilityGrid grid(MapLimits(0.05, {0, 0}, 1, 1));
  grid.SetProbability({0, 0}, kMaxProbability);
  EXPECT_FALSE(grid.ApplyLookupTable({0, 0}, ComputeLookupTableToApplyOdds(Odds(0.55f))));
  EXPECT_EQ(grid.value({0, 0}), kMaxValue);
}

TEST(ProbabilityGrid, GrowToIncludeKeepsContentsAtTheirPositions) {
  const MapLimits limits(0.05, {0.3, -0.2}, 5, 4);
  ProbabilityGrid grid(limits);
  grid.SetProbability({0, 0}, 0.2f);
  grid.SetProbability({4, 3}, 0.8f);
  grid.SetProbability({2, 1}, 0.6f);
  const Eigen::Vector2d a = limits.CellCenter({0, 0});
  const Eigen::Vector2d b = limits.CellCenter({4, 3});
  const Eigen::Vector2d c = limits.CellCenter({2, 1});

  const Eigen::Vector2d far(-1.0, 2.0);
  grid.GrowToInclude(far, 3);
  const MapLimits& grown = grid.limits();
  const CellIndex far_cell = grown.CellContaining(far);
  ASSERT_TRUE(grown.Contains(far_cell));
  EXPECT_GE(far_cell.x, 3);                       // padding on the grown -x side
  EXPECT_GE(grown.height() - 1 - far_cell.y, 3);  // and on the grown +y side
  EXPECT_DOUBLE_EQ(grown.resolution(), 0.05);
  // Only the -x and +y sides grew: old cell (0, 0) now sits after the new columns.
  const CellIndex a_now = grown.CellContaining(a);
  EXPECT_EQ(grown.width(), 5 + a_now.x);
  EXPECT_EQ(a_now.y, 0);
  EXPECT_EQ(grid.value(a_now), ProbabilityToValue(0.2f));
  EXPECT_EQ(grid.value(grown.CellContaining(b)), ProbabilityToValue(0.8f));
  EXPECT_EQ(grid.value(grown.CellContaining(c)), ProbabilityToValue(0.6f));
  // The origin moved by whole cells.
  const Eigen::Vector2d shift = (grown.origin() - limits.origin()) / 0.05;
  EXPECT_NEAR(shift.x(), std::round(shift.x()), 1e-9);
  EXPECT_NEAR(shift.y(), std::round(shift.y()), 1e-9);
}

RC_GTEST_PROP(ProbabilityGrid, GrowToIncludePreservesEveryCell, ()) {
  const int width = *rc::gen::inRange(1, 12);
  const int height = *rc::gen::inRange(1, 12);
  const MapLimits limits(0.05, {*rc::gen::inRange(-100, 100) * 0.01, 0.37}, width, height);
  ProbabilityGrid grid(limits);
  std::vector<uint16_t> before(limits.num_cells());
  for (int64_t i = 0; i < limits.num_cells(); ++i) {
    if (*rc::gen::inRange(0, 3) == 0) continue;
    grid.SetProbability(limits.CellOfFlatIndex(i), *rc::gen::inRange(10, 91) / 100.f);
    before[i] = grid.value(limits.CellOfFlatIndex(i));
  }
  const Eigen::Vector2d p(*rc::gen::inRange(-300, 300) * 0.013,
                          *rc::gen::inRange(-300, 300) * 0.011);
  const int padding = *rc::gen::inRange(0, 5);
  grid.GrowToInclude(p, padding);
  const MapLimits& grown = grid.limits();
  RC_ASSERT(grown.Contains(grown.CellContaining(p)));
  RC_ASSERT(grown.width() >= width && grown.height() >= height);
  for (int64_t i = 0; i < limits.num_cells(); ++i) {
    const CellIndex moved = grown.CellContaining(limits.CellCenter(limits.CellOfFlatIndex(i)));
    RC_ASSERT(grid.value(moved) == before[i]);
  }
  int64_t known = 0;
  for (const uint16_t raw : grid.values()) known += raw != kUnknownValue;
  RC_ASSERT(known == static_cast<int64_t>(std::count_if(before.begin(), before.end(),
                                                        [](uint16_t v) { return v != 0; })));
}

TEST(ProbabilityGrid, GrowingAnEmptyGridCentresItOnThePoint) {
  ProbabilityGrid grid;
  // Off cell borders, where rounding of the new origin cannot move the point.
  grid.GrowToInclude({10.01, -4.01}, 2);
  const CellIndex cell = grid.limits().CellContaining({10.01, -4.01});
  EXPECT_EQ(grid.limits().width(), 5);
  EXPECT_EQ(grid.limits().height(), 5);
  EXPECT_EQ(cell, (CellIndex{2, 2}));
}

TEST(ProbabilityGrid, GrowingDuringAnUpdateKeepsMarkersWithTheirCells) {
  ProbabilityGrid grid(MapLimits(0.05, {0, 0}, 3, 3));
  const std::vector<uint16_t> hit = ComputeLookupTableToApplyOdds(Odds(0.55f));
  ASSERT_TRUE(grid.ApplyLookupTable({1, 1}, hit));
  grid.GrowToInclude({-1.0, -1.0}, 1);
  const CellIndex moved = grid.limits().CellContaining({0.075, 0.075});
  EXPECT_FALSE(grid.ApplyLookupTable(moved, hit));
  grid.FinishUpdate();
  for (const uint16_t raw : grid.values()) ASSERT_FALSE(raw & kUpdateMarker);
  EXPECT_TRUE(grid.ApplyLookupTable(moved, hit));
}

}  // namespace
}  // namespace scout::grid
