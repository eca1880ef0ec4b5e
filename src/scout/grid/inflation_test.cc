#include "scout/grid/inflation.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <random>
#include <stdexcept>

namespace scout::grid {
namespace {

// Reference: blocked iff some occupied cell centre is within radius_m, by direct
// metric distance between centres.
std::vector<uint8_t> BruteForce(const std::vector<CellState>& states, const MapLimits& limits,
                                double radius_m) {
  std::vector<uint8_t> blocked(states.size(), 0);
  for (int64_t i = 0; i < limits.num_cells(); ++i) {
    for (int64_t j = 0; j < limits.num_cells(); ++j) {
      if (states[j] != CellState::kOccupied) continue;
      const double d = (limits.CellCenter(limits.CellOfFlatIndex(i)) -
                        limits.CellCenter(limits.CellOfFlatIndex(j)))
                           .norm();
      if (d <= radius_m + 1e-9) blocked[i] = 1;
    }
  }
  return blocked;
}

TEST(InflateOccupied, SingleCellGivesADiscNotASquare) {
  const MapLimits limits(0.05, {-1.0, 2.0}, 41, 41);
  std::vector<CellState> states(limits.num_cells(), CellState::kFree);
  const CellIndex centre{20, 20};
  states[limits.FlatIndex(centre)] = CellState::kOccupied;
  const std::vector<uint8_t> blocked = InflateOccupied(states, limits, 0.4);

  int count = 0;
  for (const uint8_t b : blocked) count += b;
  // Integer points with dx^2 + dy^2 <= 8^2 (Gauss circle problem, N(8) = 197).
  EXPECT_EQ(count, 197);
  EXPECT_EQ(blocked, BruteForce(states, limits, 0.4));
  const auto at = [&](int dx, int dy) {
    return blocked[limits.FlatIndex({centre.x + dx, centre.y + dy})];
  };
  EXPECT_TRUE(at(0, 0));
  EXPECT_TRUE(at(8, 0));  // exactly the radius: included
  EXPECT_TRUE(at(0, -8));
  EXPECT_FALSE(at(9, 0));
  EXPECT_TRUE(at(5, 6));   // 61 <= 64
  EXPECT_FALSE(at(6, 6));  // 72 > 64: a square kernel would block it
  EXPECT_FALSE(at(7, 4));  // 65 > 64
  EXPECT_FALSE(at(8, 8));
}

TEST(InflateOccupied, ZeroRadiusBlocksOnlyOccupiedCells) {
  const MapLimits limits(0.1, {0, 0}, 3, 2);
  const std::vector<CellState> states = {CellState::kOccupied, CellState::kFree,
                                         CellState::kUnknown,  CellState::kFree,
                                         CellState::kFree,     CellState::kOccupied};
  EXPECT_EQ(InflateOccupied(states, limits, 0.0), (std::vector<uint8_t>{1, 0, 0, 0, 0, 1}));
}

TEST(InflateOccupied, UnknownAndFreeCellsAreNotObstacles) {
  const MapLimits limits(0.05, {0, 0}, 10, 10);
  std::vector<CellState> states(limits.num_cells(), CellState::kUnknown);
  for (int i = 0; i < 10; ++i) states[i] = CellState::kFree;
  for (const uint8_t b : InflateOccupied(states, limits, 0.4)) EXPECT_EQ(b, 0);
}

TEST(InflateOccupied, RejectsBadArguments) {
  const MapLimits limits(0.05, {0, 0}, 2, 2);
  EXPECT_THROW(InflateOccupied(std::vector<CellState>(3), limits, 0.4), std::invalid_argument);
  EXPECT_THROW(InflateOccupied(std::vector<CellState>(4), limits, -0.1), std::invalid_argument);
}

RC_GTEST_PROP(InflateOccupied, EqualsBruteForceOnRandomMaps, ()) {
  const int width = *rc::gen::inRange(1, 16);
  const int height = *rc::gen::inRange(1, 16);
  const double resolution = *rc::gen::element(0.05, 0.1, 0.25);
  const MapLimits limits(resolution, {0.5, -0.5}, width, height);
  std::vector<CellState> states(limits.num_cells());
  for (auto& s : states) {
    s = *rc::gen::element(CellState::kFree, CellState::kFree, CellState::kUnknown,
                          CellState::kOccupied);
  }
  // Radii on whole cells hit the "exactly k cells" boundary; others fall between.
  const double radius_m = *rc::gen::inRange(0, 25) * resolution / *rc::gen::element(1, 3);
  RC_ASSERT(InflateOccupied(states, limits, radius_m) == BruteForce(states, limits, radius_m));
}

RC_GTEST_PROP(InflationLevels, CountsTheRadiiEachCellLiesWithin, ()) {
  const int width = *rc::gen::inRange(1, 16);
  const int height = *rc::gen::inRange(1, 16);
  const MapLimits limits(0.1, {0.0, 0.0}, width, height);
  std::vector<CellState> states(limits.num_cells());
  for (auto& s : states) {
    s = *rc::gen::element(CellState::kFree, CellState::kUnknown, CellState::kOccupied);
  }
  const std::vector<double> radii = {*rc::gen::inRange(0, 40) * 0.05,
                                     *rc::gen::inRange(0, 40) * 0.05};
  std::vector<uint8_t> expected(states.size(), 0);
  for (const double r : radii) {
    const std::vector<uint8_t> one = BruteForce(states, limits, r);
    for (size_t i = 0; i < one.size(); ++i) expected[i] += one[i];
  }
  RC_ASSERT(InflationLevels(states, limits, radii) == expected);
}

// Grids of maps (millions of cells) are split between threads by rows and
// columns; the result must not depend on where the blocks meet.
TEST(InflationLevels, LargeGridsSplitBetweenThreadsEqualTheDirectMarking) {
  const MapLimits limits(0.05, {0.0, 0.0}, 701, 613);
  std::vector<CellState> states(limits.num_cells(), CellState::kFree);
  std::mt19937 random(7);
  std::vector<CellIndex> occupied;
  for (int i = 0; i < 3000; ++i) {
    const CellIndex c{static_cast<int>(random() % 701), static_cast<int>(random() % 613)};
    states[limits.FlatIndex(c)] = CellState::kOccupied;
    occupied.push_back(c);
  }
  const std::vector<double> radii = {0.40, 0.30};
  std::vector<uint8_t> expected(states.size(), 0);
  for (const double r : radii) {
    std::vector<uint8_t> one(states.size(), 0);
    const int reach = static_cast<int>(r / 0.05) + 1;
    for (const CellIndex& o : occupied) {
      for (int y = o.y - reach; y <= o.y + reach; ++y) {
        for (int x = o.x - reach; x <= o.x + reach; ++x) {
          const CellIndex c{x, y};
          if (!limits.Contains(c)) continue;
          if ((limits.CellCenter(c) - limits.CellCenter(o)).norm() <= r + 1e-9) {
            one[limits.FlatIndex(c)] = 1;
          }
        }
      }
    }
    for (size_t i = 0; i < one.size(); ++i) expected[i] += one[i];
  }
  EXPECT_TRUE(InflationLevels(states, limits, radii) == expected);
}

TEST(InflationLevels, RejectsNoRadii) {
  const MapLimits limits(0.05, {0, 0}, 2, 2);
  EXPECT_THROW(InflationLevels(std::vector<CellState>(4), limits, {}), std::invalid_argument);
}

}  // namespace
}  // namespace scout::grid
