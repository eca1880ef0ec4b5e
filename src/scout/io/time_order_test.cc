#include "scout/io/time_order.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <vector>

namespace scout::io {
namespace {

std::vector<double> Kept(const std::vector<double>& times) {
  const std::vector<bool> keep = LongestTimeOrder(times);
  std::vector<double> kept;
  for (size_t i = 0; i < times.size(); ++i) {
    if (keep[i]) kept.push_back(times[i]);
  }
  return kept;
}

TEST(LongestTimeOrder, OneStampFarInTheFutureLosesOnlyItself) {
  EXPECT_EQ(Kept({1, 2, 1e9, 3, 4, 5}), (std::vector<double>{1, 2, 3, 4, 5}));
  // Dropping whatever is earlier than the last kept stamp would keep 1, 2, 1e9.
}

TEST(LongestTimeOrder, OfEquallyLongRunsTheEarliestArrivalsAreKept) {
  // 1 3 3 and 1 2 3 are both longest: the 3 that came first stays.
  EXPECT_EQ(LongestTimeOrder({1, 3, 2, 3}), (std::vector<bool>{true, true, false, true}));
  EXPECT_EQ(LongestTimeOrder({5, 4, 3}), (std::vector<bool>{true, false, false}));
}

TEST(LongestTimeOrder, EqualTimesAreKeptAndEmptyInputIsEmpty) {
  EXPECT_EQ(Kept({2, 2, 2}), (std::vector<double>{2, 2, 2}));
  EXPECT_TRUE(LongestTimeOrder({}).empty());
}

// Length of the longest non-decreasing subsequence, by the quadratic recurrence.
size_t LongestByDynamicProgramming(const std::vector<double>& t) {
  std::vector<size_t> ending(t.size(), 1);
  size_t best = 0;
  for (size_t i = 0; i < t.size(); ++i) {
    for (size_t j = 0; j < i; ++j) {
      if (t[j] <= t[i]) ending[i] = std::max(ending[i], ending[j] + 1);
    }
    best = std::max(best, ending[i]);
  }
  return best;
}

RC_GTEST_PROP(LongestTimeOrder, KeepsANonDecreasingRunOfTheLongestLength, ()) {
  const std::vector<int> raw = *rc::gen::container<std::vector<int>>(rc::gen::inRange(0, 20));
  const std::vector<double> times(raw.begin(), raw.end());
  const std::vector<double> kept = Kept(times);
  RC_ASSERT(std::is_sorted(kept.begin(), kept.end()));
  RC_ASSERT(kept.size() == LongestByDynamicProgramming(times));
}

}  // namespace
}  // namespace scout::io
