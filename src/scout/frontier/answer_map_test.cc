#include "scout/frontier/answer_map.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "scout/frontier/test_grids.h"

namespace scout::frontier {
namespace {

using testing::DrawGrid;

// A w x h grid of random cells: of every 10 draws, 'free_in_10' give free
// ('.'), the next 'occupied_in_10' occupied ('#'), the rest unknown ('?').
std::vector<std::string> RandomRows(std::mt19937_64& rng, int w, int h, int free_in_10,
                                    int occupied_in_10) {
  std::vector<std::string> rows(h, std::string(w, '?'));
  for (auto& row : rows) {
    for (char& ch : row) {
      const int r = static_cast<int>(rng() % 10);
      ch = r < free_in_10 ? '.' : (r < free_in_10 + occupied_in_10 ? '#' : '?');
    }
  }
  return rows;
}

// Uniform in [lo, hi) from 53 random bits.
double Uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng() >> 11) / static_cast<double>(1ull << 53);
}

TEST(AnswerMap, KnownNonFrontierCellsObject) {
  const auto g = DrawGrid({"?????",  //
                           "?...?",  //
                           "?...?",  //
                           "?...?",  //
                           "?##??"},
                          0.1);
  const AnswerMap a(g->States(), g->limits());
  EXPECT_TRUE(a.ObjectsAtCell({2, 2}));   // free, every neighbour known
  EXPECT_TRUE(a.ObjectsAtCell({1, 0}));   // occupied
  EXPECT_FALSE(a.ObjectsAtCell({1, 1}));  // free frontier cell (touches unknown (0, 1))
  EXPECT_FALSE(a.ObjectsAtCell({4, 4}));  // unknown
  EXPECT_FALSE(a.Objects({-1.0, 0.0}));   // outside the grid
  EXPECT_TRUE(a.Objects({0.25, 0.25}));
}

// Random grids: every position within Margin(q) of q gets q's answer.
RC_GTEST_PROP(AnswerMap, MarginIsConservative, ()) {
  const uint64_t seed = *rc::gen::arbitrary<uint64_t>();
  std::mt19937_64 rng(seed);
  const int w = 6 + static_cast<int>(rng() % 20), h = 6 + static_cast<int>(rng() % 20);
  const std::vector<std::string> rows = RandomRows(rng, w, h, 5, 2);
  const double res = 0.05;
  const auto g = DrawGrid(rows, res, {-0.3, 0.7});
  const AnswerMap a(g->States(), g->limits());
  const auto uniform = [&](double lo, double hi) { return Uniform(rng, lo, hi); };
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Vector2d q(uniform(-0.6, -0.3 + w * res + 0.3), uniform(0.4, 0.7 + h * res + 0.3));
    const double m = a.Margin(q);
    RC_ASSERT(m >= 0.0);
    const double step = std::min(m, 2.0) * uniform(0.0, 0.999);
    const double angle = uniform(0.0, 6.283);
    const Eigen::Vector2d q2 = q + step * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    RC_ASSERT(a.Objects(q2) == a.Objects(q));
  }
}

// Random grids: within 1.4 cells of another answer the margin is the exact
// distance to it (the window scan, which stops early once no farther ring can
// matter, must still find the nearest cell and nothing nearer than it).
RC_GTEST_PROP(AnswerMap, MarginIsTheDistanceToANearbyOtherAnswer, ()) {
  const uint64_t seed = *rc::gen::arbitrary<uint64_t>();
  std::mt19937_64 rng(seed);
  const int w = 4 + static_cast<int>(rng() % 12), h = 4 + static_cast<int>(rng() % 12);
  const std::vector<std::string> rows = RandomRows(rng, w, h, 6, 2);
  const double res = 0.05;
  const auto g = DrawGrid(rows, res, {0.4, -0.2});
  const AnswerMap a(g->States(), g->limits());
  const grid::MapLimits& limits = g->limits();
  const geometry::Box2d bounds = limits.Bounds();
  const auto uniform = [&](double lo, double hi) { return Uniform(rng, lo, hi); };
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Vector2d q(uniform(bounds.min.x(), bounds.max.x()),
                            uniform(bounds.min.y(), bounds.max.y()));
    const bool objects = a.Objects(q);
    // Brute force over every cell's square; outside the grid nobody objects.
    double nearest = objects ? std::min({q.x() - bounds.min.x(), bounds.max.x() - q.x(),
                                         q.y() - bounds.min.y(), bounds.max.y() - q.y()})
                             : std::numeric_limits<double>::infinity();
    for (int64_t flat = 0; flat < limits.num_cells(); ++flat) {
      const grid::CellIndex c = limits.CellOfFlatIndex(flat);
      if (a.ObjectsAtCell(c) == objects) continue;
      const Eigen::Vector2d lo = limits.CellCenter(c).array() - 0.5 * res;
      const Eigen::Vector2d hi = limits.CellCenter(c).array() + 0.5 * res;
      const double dx = std::max({lo.x() - q.x(), 0.0, q.x() - hi.x()});
      const double dy = std::max({lo.y() - q.y(), 0.0, q.y() - hi.y()});
      nearest = std::min(nearest, std::sqrt(dx * dx + dy * dy));
    }
    // Up to 1.4 cells the other answer's cell centre lies within 2 sqrt(2)
    // cells of q's cell centre, so Margin scans the window, whose edge lies
    // at least 1.5 cells away; both of its rings can hold the nearest cell.
    if (nearest >= 1.4 * res) continue;
    RC_ASSERT(std::abs(a.Margin(q) - nearest) <= 1e-12);
  }
}

TEST(AnswerMap, MarginIsTightNearABoundary) {
  // One objecting column next to unknown: a point 0.01 m from the boundary has a
  // margin of about 0.01 m, not 0.
  const auto g = DrawGrid({"##??", "##??", "##??", "##??"}, 0.1);
  const AnswerMap a(g->States(), g->limits());
  EXPECT_NEAR(a.Margin({0.19, 0.2}), 0.01, 1e-9);
  EXPECT_NEAR(a.Margin({0.25, 0.2}), 0.05, 1e-9);
}

TEST(AnswerMap, EmptyMapNeverObjects) {
  const auto g = DrawGrid({"????", "????"}, 0.1);
  const AnswerMap a(g->States(), g->limits());
  EXPECT_EQ(a.num_objecting_cells(), 0);
  EXPECT_TRUE(std::isinf(a.Margin({0.1, 0.1})));
}

}  // namespace
}  // namespace scout::frontier
