#include "scout/io/trajectory_association.h"

#include <gtest/gtest.h>

#include <cmath>

namespace scout::io {
namespace {

using IndexPairs = std::vector<std::pair<int, int>>;

TEST(AssociateByTime, PairsNearestReferenceWithinMaxDt) {
  const std::vector<StampedPose> estimate = {{0.0, geometry::Rigid2d(0, 0, 0)},
                                             {3.4, geometry::Rigid2d(3, 0, 0)},
                                             {1.0, geometry::Rigid2d(1, 0, 0)},
                                             {2.0, geometry::Rigid2d(2, 0, 0)}};
  const std::vector<StampedPose> reference = {{3.41, geometry::Rigid2d(30, 0, 0)},
                                              {0.02, geometry::Rigid2d(0, 0, 0)},
                                              {0.98, geometry::Rigid2d(10, 0, 0)},
                                              {1.07, geometry::Rigid2d(11, 0, 0)},
                                              {2.3, geometry::Rigid2d(20, 0, 0)}};
  const std::vector<PosePair> pairs = AssociateByTime(estimate, reference, 0.1);
  ASSERT_EQ(pairs.size(), 3u);  // 2.0 s is 0.3 s from its nearest reference
  EXPECT_EQ(pairs[0].time_s, 0.0);
  EXPECT_EQ(pairs[0].reference.x(), 0.0);
  EXPECT_EQ(pairs[1].time_s, 3.4);
  EXPECT_EQ(pairs[1].reference.x(), 30.0);
  EXPECT_EQ(pairs[2].time_s, 1.0);
  EXPECT_EQ(pairs[2].reference.x(), 10.0);  // 0.98 is nearer than 1.07
  EXPECT_EQ(pairs[2].estimate.x(), 1.0);
}

// A reproducible 360-beam scan for 'reading' (no two readings alike).
std::vector<float> Scan(int reading) {
  std::vector<float> ranges(360);
  for (int k = 0; k < 360; ++k) {
    ranges[k] = static_cast<float>(
        0.5 + std::fmod(reading * 7.31 + k * 0.377 + 3.0 * std::sin(0.1 * reading * k), 20.0));
  }
  return ranges;
}

// The scan as a CARMEN log prints it: 2 decimals, and a 361st beam.
std::vector<float> Printed(const std::vector<float>& scan) {
  std::vector<float> printed;
  for (float r : scan) printed.push_back(static_cast<float>(std::round(r * 100.0) / 100.0));
  printed.push_back(1.0f);
  return printed;
}

TEST(MatchScansByRanges, RoundedCopiesWithDuplicatesAndMissingScans) {
  // Recording b: readings repeat while the robot stands still at b 10..12,
  // 15..19 and 30..33.
  std::vector<int> reading_of_b;
  for (int j = 0; j < 40; ++j) {
    reading_of_b.push_back(j >= 11 && j <= 12   ? 10
                           : j >= 16 && j <= 19 ? 15
                           : j >= 31 && j <= 33 ? 30
                                                : j);
  }
  std::vector<std::vector<float>> b;
  for (int reading : reading_of_b) b.push_back(Scan(reading));
  // A beam just below a rounding boundary in b and just above it in a: the
  // hash misses this pair, the direct comparison must find it.
  b[5][100] = 2.3449f;
  // Recording a holds one copy of the b 10..12 reading, all five of 15..19,
  // three of the four of 30..33; b 25 is missing; and a ends with a scan b
  // never saw.
  std::vector<int> sources;
  for (int j = 0; j < 40; ++j) {
    if (j == 10 || j == 12 || j == 25 || j == 32) continue;
    sources.push_back(j);
  }
  std::vector<std::vector<float>> a;
  for (int j : sources) a.push_back(Printed(b[j]));
  a[5][100] = 2.3451f;
  a.push_back(Printed(Scan(1000)));

  const IndexPairs matches = MatchScansByRanges(a, b, 0.01);
  ASSERT_EQ(matches.size(), sources.size());  // all but the foreign scan
  for (size_t k = 0; k < matches.size(); ++k) {
    EXPECT_EQ(matches[k].first, static_cast<int>(k));
    if (k > 0) {
      EXPECT_GT(matches[k].second, matches[k - 1].second);
    }
    EXPECT_EQ(reading_of_b[matches[k].second], reading_of_b[sources[k]]) << "a " << k;
    // Where the reading is unambiguous or the run is complete, the match is exact.
    if (sources[k] < 30 || sources[k] > 33) {
      EXPECT_EQ(matches[k].second, sources[k]) << "a " << k;
    }
  }
  // The single copy of the 10..12 reading sits between a 9 (b 9) and a 11
  // (b 13): the closest progression is b 11.
  EXPECT_EQ(matches[10].second, 11);
  // Three of four copies: any increasing choice is valid, bounded by the run.
  EXPECT_EQ(matches[27].second, 30);
  EXPECT_EQ(matches[29].second, 33);
}

TEST(MatchScansByRanges, DifferentReadingsOrBeamCountsDoNotMatch) {
  std::vector<float> scan = Scan(3);
  std::vector<float> shifted = scan;
  shifted[200] += 0.02f;  // beyond half the print resolution
  std::vector<float> short_scan(scan.begin(), scan.end() - 2);
  EXPECT_TRUE(MatchScansByRanges({shifted}, {scan}, 0.01).empty());
  EXPECT_TRUE(MatchScansByRanges({short_scan}, {scan}, 0.01).empty());
  EXPECT_EQ(MatchScansByRanges({Printed(scan)}, {scan}, 0.01), (IndexPairs{{0, 0}}));
  EXPECT_TRUE(MatchScansByRanges({}, {scan}, 0.01).empty());
}

TEST(MatchScansByRanges, NonFiniteRangesMatchOnlyNonFinite) {
  std::vector<float> scan = Scan(4);
  scan[7] = INFINITY;
  std::vector<float> nan_copy = scan;
  nan_copy[7] = NAN;
  std::vector<float> finite_copy = scan;
  finite_copy[7] = 5.0f;
  EXPECT_EQ(MatchScansByRanges({nan_copy}, {scan}, 0.01), (IndexPairs{{0, 0}}));
  EXPECT_TRUE(MatchScansByRanges({finite_copy}, {scan}, 0.01).empty());
}

}  // namespace
}  // namespace scout::io

namespace scout::io {
namespace {

TEST(PairByIndexTest, PairsOnlyTheIndicesThatHaveAReferencePose) {
  const std::vector<StampedPose> estimate = {{1.0, geometry::Rigid2d(0.0, 0.0, 0.0)},
                                             {2.0, geometry::Rigid2d(1.0, 0.0, 0.0)},
                                             {3.0, geometry::Rigid2d(2.0, 0.0, 0.0)}};
  const std::vector<std::optional<geometry::Rigid2d>> reference = {
      geometry::Rigid2d(0.1, 0.0, 0.0), std::nullopt, geometry::Rigid2d(2.1, 0.0, 0.0)};
  const std::vector<PosePair> pairs = PairByIndex(estimate, reference);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].time_s, 1.0);
  EXPECT_EQ(pairs[1].time_s, 3.0);
  EXPECT_DOUBLE_EQ(pairs[1].estimate.x(), 2.0);
  EXPECT_DOUBLE_EQ(pairs[1].reference.x(), 2.1);
  // A reference shorter than the estimate pairs only what it covers.
  EXPECT_EQ(PairByIndex(estimate, {reference[0]}).size(), 1u);
}

}  // namespace
}  // namespace scout::io
