#include "scout/sim/random.h"

#include <gtest/gtest.h>

#include <cmath>

namespace scout::sim {
namespace {

TEST(Random, SameSeedGivesSameSequence) {
  std::mt19937_64 a(7), b(7);
  for (int i = 0; i < 100; ++i) {
    EXPECT_EQ(UniformReal(a, -1.0, 2.0), UniformReal(b, -1.0, 2.0));
    EXPECT_EQ(StandardNormal(a), StandardNormal(b));
  }
}

TEST(Random, UniformIntCoversInclusiveRange) {
  std::mt19937_64 rng(1);
  int counts[4] = {0, 0, 0, 0};
  for (int i = 0; i < 4000; ++i) {
    const int v = UniformInt(rng, 2, 5);
    ASSERT_GE(v, 2);
    ASSERT_LE(v, 5);
    ++counts[v - 2];
  }
  for (int c : counts) EXPECT_GT(c, 800);
}

TEST(Random, StandardNormalHasUnitVariance) {
  std::mt19937_64 rng(3);
  const int n = 20000;
  double sum = 0.0, sum_sq = 0.0;
  for (int i = 0; i < n; ++i) {
    const double v = StandardNormal(rng);
    sum += v;
    sum_sq += v * v;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.03);
  EXPECT_NEAR(std::sqrt(sum_sq / n), 1.0, 0.03);
}

TEST(Random, DerivedSeedsDiffer) {
  EXPECT_NE(DeriveSeed(1, 0), DeriveSeed(1, 1));
  EXPECT_NE(DeriveSeed(1, 0), DeriveSeed(2, 0));
  EXPECT_EQ(DeriveSeed(5, 3), DeriveSeed(5, 3));
}

}  // namespace
}  // namespace scout::sim
