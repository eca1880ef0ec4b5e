#include "scout/explore/mean_shift.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace scout::explore {
namespace {

// Mean-shift as ALGORITHMS §6.1 states it, every seed shifted on its own to
// the end, neighbours by brute force. On points whose coordinates are
// multiples of 1/8 m every kernel's sum is exact, so its means do not depend
// on the order the points are added in, and MeanShift must agree with it bit
// for bit.
MeanShiftClusters PlainMeanShift(const std::vector<Eigen::Vector2d>& points,
                                 const std::vector<Eigen::Vector2d>& seeds,
                                 const MeanShiftOptions& o) {
  const double h = o.bandwidth_m;
  struct Mode {
    Eigen::Vector2d position;
    int support;
  };
  std::vector<Mode> modes;
  for (Eigen::Vector2d x : seeds) {
    int support = 0;
    for (int it = 0; it < o.max_iterations; ++it) {
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      int n = 0;
      for (const Eigen::Vector2d& q : points) {
        if ((q - x).squaredNorm() <= h * h) sum += q, ++n;
      }
      if (n == 0) break;
      const Eigen::Vector2d next = sum / n;
      const double shift = (next - x).norm();
      x = next, support = n;
      if (shift < o.convergence_m) break;
    }
    modes.push_back({x, support});
  }
  std::stable_sort(modes.begin(), modes.end(),
                   [](const Mode& a, const Mode& b) { return a.support > b.support; });
  MeanShiftClusters out;
  for (const Mode& m : modes) {
    if (std::none_of(out.centres.begin(), out.centres.end(), [&](const Eigen::Vector2d& c) {
          return (c - m.position).squaredNorm() < h * h;
        })) {
      out.centres.push_back(m.position);
    }
  }
  for (const Eigen::Vector2d& p : points) {
    int best = -1;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (int c = 0; c < static_cast<int>(out.centres.size()); ++c) {
      const double d2 = (out.centres[c] - p).squaredNorm();
      if (d2 < best_d2) best_d2 = d2, best = c;
    }
    out.label.push_back(best);
  }
  return out;
}

TEST(MeanShiftTest, TwoSeparateLinesGiveTwoCentresAtTheirMiddles) {
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i <= 10; ++i) points.emplace_back(0.05 * i, 0.0);         // 0 .. 0.5 m
  for (int i = 0; i <= 10; ++i) points.emplace_back(10.0, 2.0 + 0.05 * i);  // 2 .. 2.5 m
  const MeanShiftClusters c = MeanShift(points, {});
  ASSERT_EQ(c.centres.size(), 2u);
  std::vector<Eigen::Vector2d> centres = c.centres;
  std::sort(centres.begin(), centres.end(),
            [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() < b.x(); });
  EXPECT_NEAR((centres[0] - Eigen::Vector2d(0.25, 0.0)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((centres[1] - Eigen::Vector2d(10.0, 2.25)).norm(), 0.0, 1e-9);
  for (int i = 1; i <= 10; ++i) EXPECT_EQ(c.label[i], c.label[0]);
  for (int i = 12; i <= 21; ++i) EXPECT_EQ(c.label[i], c.label[11]);
  EXPECT_NE(c.label[0], c.label[11]);
}

// On a long even line the seeds near its ends walk inward, half the way to
// where the kernel lies wholly on the line per shift, and meet on the same
// positions. Seeded from the east end to the west, a seed nearer the west
// end comes later and reaches a position another seed left at an earlier
// shift, so it may take that seed's end only when its own budget lasts as
// long; under every budget the result must be the reference's.
TEST(MeanShiftTest, ReusedShiftsKeepEveryBudgetOfALongLine) {
  std::vector<Eigen::Vector2d> points;
  for (int i = 159; i >= 0; --i) points.emplace_back(i / 8.0, 0.0);  // 20 m
  for (int iterations = 1; iterations <= 40; ++iterations) {
    MeanShiftOptions o;
    o.bandwidth_m = 0.5;
    o.seed_bin_m = 0.0;
    o.max_iterations = iterations;
    // Ended by a shift of exactly 0 (a kernel's points stay the same), a
    // shift one budget short of the end leaves the same position; a coarse
    // convergence ends on a shift that moves.
    o.convergence_m = iterations % 2 == 0 ? 0.1 : 1e-3;
    const MeanShiftClusters fast = MeanShift(points, o);
    const MeanShiftClusters plain = PlainMeanShift(points, points, o);
    ASSERT_EQ(fast.centres.size(), plain.centres.size()) << iterations << " shifts";
    for (size_t i = 0; i < fast.centres.size(); ++i) {
      EXPECT_EQ(fast.centres[i].x(), plain.centres[i].x()) << iterations << " shifts";
      EXPECT_EQ(fast.centres[i].y(), plain.centres[i].y()) << iterations << " shifts";
    }
    EXPECT_EQ(fast.label, plain.label) << iterations << " shifts";
  }
}

// Seeds at every point (seed_bin_m 0) keep the seeds known to the reference.
RC_GTEST_PROP(MeanShiftProperty, EqualsShiftingEverySeedToTheEnd, ()) {
  std::vector<Eigen::Vector2d> points;
  // Blobs and lines of points on a 1/8 m lattice, the shapes frontiers have.
  const int pieces = *rc::gen::inRange(1, 6);
  for (int k = 0; k < pieces; ++k) {
    const int cx = *rc::gen::inRange(-40, 40), cy = *rc::gen::inRange(-40, 40);
    const bool line = *rc::gen::arbitrary<bool>();
    const int n = line ? *rc::gen::inRange(1, 120) : *rc::gen::inRange(1, 40);
    for (int i = 0; i < n; ++i) {
      const int dx = line ? i : *rc::gen::inRange(-6, 7);
      const int dy = line ? *rc::gen::inRange(0, 2) : *rc::gen::inRange(-6, 7);
      points.emplace_back((cx + dx) / 8.0, (cy + dy) / 8.0);
    }
  }
  MeanShiftOptions o;
  o.bandwidth_m = *rc::gen::inRange(2, 16) / 8.0;
  o.seed_bin_m = 0.0;
  o.max_iterations = *rc::gen::element(1, 2, 3, 4, 5, 6, 8, 100);
  o.convergence_m = *rc::gen::element(1e-9, 1e-3, 0.05);
  const MeanShiftClusters fast = MeanShift(points, o);
  const MeanShiftClusters plain = PlainMeanShift(points, points, o);
  RC_ASSERT(fast.centres.size() == plain.centres.size());
  for (size_t i = 0; i < fast.centres.size(); ++i) {
    RC_ASSERT(fast.centres[i].x() == plain.centres[i].x());
    RC_ASSERT(fast.centres[i].y() == plain.centres[i].y());
  }
  RC_ASSERT(fast.label == plain.label);
}

}  // namespace
}  // namespace scout::explore
