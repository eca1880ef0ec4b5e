#include "scout/grid/distance_transform.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace scout::grid {
namespace {

// O(n^2) reference: squared distance from every cell to the nearest site.
std::vector<float> BruteForce(const std::vector<uint8_t>& is_site, int width, int height) {
  std::vector<float> result(is_site.size(), std::numeric_limits<float>::infinity());
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (int sy = 0; sy < height; ++sy) {
        for (int sx = 0; sx < width; ++sx) {
          if (!is_site[sy * width + sx]) continue;
          const float d2 = static_cast<float>((x - sx) * (x - sx) + (y - sy) * (y - sy));
          result[y * width + x] = std::min(result[y * width + x], d2);
        }
      }
    }
  }
  return result;
}

RC_GTEST_PROP(SquaredDistanceToNearestSite, EqualsBruteForceOnRandomMasks, ()) {
  const int width = *rc::gen::inRange(1, 24);
  const int height = *rc::gen::inRange(1, 24);
  // Densities from "almost no sites" to "almost all sites" reach both regimes of
  // the lower envelope (long gaps and many overlapping parabolas).
  const int percent = *rc::gen::inRange(0, 101);
  std::vector<uint8_t> mask(width * height);
  for (auto& m : mask) m = *rc::gen::inRange(0, 100) < percent;
  const std::vector<float> edt = SquaredDistanceToNearestSite(mask, width, height);
  RC_ASSERT(edt == BruteForce(mask, width, height));
}

// Grids of maps (millions of cells) are split between threads by rows and
// columns; the result must not depend on where the blocks meet.
TEST(SquaredDistanceToNearestSite, LargeGridsSplitBetweenThreadsEqualTheNearestSiteByHand) {
  const int width = 811, height = 597;
  std::vector<uint8_t> mask(width * height, 0);
  std::mt19937 random(11);
  std::vector<std::array<int, 2>> sites;
  for (int i = 0; i < 25; ++i) {
    const int x = static_cast<int>(random() % width), y = static_cast<int>(random() % height);
    mask[y * width + x] = 1;
    sites.push_back({x, y});
  }
  const std::vector<float> edt = SquaredDistanceToNearestSite(mask, width, height);
  int64_t mismatches = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      float best = std::numeric_limits<float>::infinity();
      for (const auto& [sx, sy] : sites) {
        best = std::min(best, static_cast<float>((x - sx) * (x - sx) + (y - sy) * (y - sy)));
      }
      mismatches += edt[y * width + x] != best;
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(SquaredDistanceToNearestSite, NoSiteGivesInfinity) {
  const std::vector<float> edt = SquaredDistanceToNearestSite(std::vector<uint8_t>(35, 0), 7, 5);
  ASSERT_EQ(edt.size(), 35u);
  for (const float d : edt) EXPECT_EQ(d, std::numeric_limits<float>::infinity());
}

TEST(SquaredDistanceToNearestSite, SingleSiteGivesSquaredEuclideanDistance) {
  const int width = 9, height = 6;
  std::vector<uint8_t> mask(width * height, 0);
  mask[2 * width + 3] = 1;
  const std::vector<float> edt = SquaredDistanceToNearestSite(mask, width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      EXPECT_EQ(edt[y * width + x], static_cast<float>((x - 3) * (x - 3) + (y - 2) * (y - 2)));
    }
  }
}

TEST(SquaredDistanceToNearestSite, SitesInOnlySomeRowsStillReachAllRows) {
  // Rows without a site are all-infinite after the first pass; the second pass
  // must fill them from other rows.
  const int width = 4, height = 7;
  std::vector<uint8_t> mask(width * height, 0);
  mask[6 * width + 0] = 1;
  const std::vector<float> edt = SquaredDistanceToNearestSite(mask, width, height);
  EXPECT_EQ(edt[0 * width + 3], 9.f + 36.f);
  EXPECT_EQ(edt, BruteForce(mask, width, height));
}

TEST(SquaredDistanceToNearestSite, EmptyGridAndSizeMismatch) {
  EXPECT_TRUE(SquaredDistanceToNearestSite({}, 0, 0).empty());
  EXPECT_TRUE(SquaredDistanceToNearestSite({}, 5, 0).empty());
  EXPECT_THROW(SquaredDistanceToNearestSite(std::vector<uint8_t>(5, 0), 2, 2),
               std::invalid_argument);
  EXPECT_THROW(SquaredDistanceToNearestSite({}, -1, 0), std::invalid_argument);
}

}  // namespace
}  // namespace scout::grid
