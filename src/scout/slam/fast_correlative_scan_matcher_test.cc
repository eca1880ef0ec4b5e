#include "scout/slam/fast_correlative_scan_matcher.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <stdexcept>

#include "scout/grid/probability_values.h"
#include "scout/slam/test_scene.h"

namespace scout::slam {
namespace {

using geometry::Rigid2d;

// Calls fn(x, y, score) for every candidate of the set documented in the
// header (x, y: translation offset in cells), by exhaustive search, with
// unknown and outside cells at kMinProbability.
template <typename Fn>
void ForEachCandidate(const grid::ProbabilityGrid& grid, const Rigid2d& initial,
                      const PointCloud& points, double linear_window_m, double angular_window_rad,
                      Fn fn) {
  const grid::MapLimits& limits = grid.limits();
  double max_range_m = 0.0;
  for (const Eigen::Vector2d& p : points) max_range_m = std::max(max_range_m, p.norm());
  const double step = AngularSearchStep(max_range_m, limits.resolution());
  const int n = static_cast<int>(std::ceil(angular_window_rad / step));
  const int bound = static_cast<int>(std::ceil(linear_window_m / limits.resolution()));
  for (int k = -n; k <= n; ++k) {
    const Rigid2d pose(initial.translation(), initial.theta() + k * step);
    std::vector<grid::CellIndex> cells;
    for (const Eigen::Vector2d& p : points) cells.push_back(limits.CellContaining(pose * p));
    for (int x = -bound; x <= bound; ++x) {
      for (int y = -bound; y <= bound; ++y) {
        int64_t sum = 0;
        for (const grid::CellIndex& c : cells) {
          const uint16_t v = grid.value({c.x + x, c.y + y});
          sum += v == grid::kUnknownValue ? 1 : v;
        }
        // Probability is linear in the raw value: 1 -> 0.1, 32767 -> 0.9.
        const double mean_value = static_cast<double>(sum) / static_cast<double>(points.size());
        fn(x, y, 0.1 + (mean_value - 1.0) * 0.8 / (grid::kMaxValue - 1));
      }
    }
  }
}

double BruteForceBestScore(const grid::ProbabilityGrid& grid, const Rigid2d& initial,
                           const PointCloud& points, double linear_window_m,
                           double angular_window_rad) {
  double best = -std::numeric_limits<double>::infinity();
  ForEachCandidate(grid, initial, points, linear_window_m, angular_window_rad,
                   [&best](int, int, double score) { best = std::max(best, score); });
  return best;
}

// A random small grid (about a third unknown, the rest any probability, so
// ties are rare but possible), scan and initial pose.
struct RandomScene {
  grid::ProbabilityGrid grid;
  PointCloud points;
  Rigid2d initial;
};

RandomScene GenerateScene() {
  const int width = *rc::gen::inRange(1, 24);
  const int height = *rc::gen::inRange(1, 24);
  RandomScene scene{
      grid::ProbabilityGrid(grid::MapLimits(0.1, {-1.0, -0.5}, width, height)), {}, Rigid2d()};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (*rc::gen::inRange(0, 3) == 0) continue;
      scene.grid.SetProbability({x, y}, static_cast<float>(*rc::gen::inRange(100, 901)) / 1000.f);
    }
  }
  const int num_points = *rc::gen::inRange(1, 12);
  for (int i = 0; i < num_points; ++i) {
    scene.points.push_back(
        {*rc::gen::inRange(-150, 151) / 100.0, *rc::gen::inRange(-150, 151) / 100.0});
  }
  scene.initial = Rigid2d(*rc::gen::inRange(-50, 150) / 100.0, *rc::gen::inRange(-50, 150) / 100.0,
                          *rc::gen::inRange(-314, 315) / 100.0);
  return scene;
}

// Random windows small enough for brute force, and a random tree depth.
FastCorrelativeScanMatcherOptions GenerateSmallWindows() {
  FastCorrelativeScanMatcherOptions options;
  options.linear_search_window_m = *rc::gen::inRange(0, 80) / 100.0;
  options.angular_search_window_rad = *rc::gen::inRange(0, 30) / 100.0;
  options.branch_and_bound_depth = *rc::gen::inRange(1, 6);
  return options;
}

RC_GTEST_PROP(FastCorrelativeScanMatcherProperty, EqualsBruteForceOnSmallWindows, ()) {
  const RandomScene scene = GenerateScene();
  FastCorrelativeScanMatcherOptions options = GenerateSmallWindows();
  options.ambiguity_radius_m = 0.0;  // brute force knows no ambiguity test
  const FastCorrelativeScanMatcher matcher(scene.grid, options);

  const double expected =
      BruteForceBestScore(scene.grid, scene.initial, scene.points, options.linear_search_window_m,
                          options.angular_search_window_rad);
  const std::optional<ScanMatchResult> result = matcher.Match(scene.initial, scene.points, 0.0);
  RC_ASSERT(result.has_value());
  // Distinct sums differ by far more than 1e-12 in score.
  RC_ASSERT(std::abs(result->score - expected) < 1e-12);
  // The threshold is inclusive of the best score and excludes anything above it.
  RC_ASSERT(matcher.Match(scene.initial, scene.points, expected - 1e-9).has_value());
  RC_ASSERT(!matcher.Match(scene.initial, scene.points, expected + 1e-9).has_value());
}

// The ambiguity test stops at the first rival it finds (whether one exists is
// all it asks): its verdict must be the exhaustive search's, a candidate
// beyond ambiguity_radius_m of the best scoring within the margin of it.
RC_GTEST_PROP(FastCorrelativeScanMatcherProperty, AmbiguityEqualsBruteForceOnSmallWindows, ()) {
  const RandomScene scene = GenerateScene();
  FastCorrelativeScanMatcherOptions options = GenerateSmallWindows();
  options.ambiguity_radius_m = *rc::gen::inRange(1, 40) / 100.0;
  options.ambiguity_score_margin = *rc::gen::inRange(0, 20) / 100.0;
  FastCorrelativeScanMatcherOptions blind_options = options;
  blind_options.ambiguity_radius_m = 0.0;
  const std::optional<ScanMatchResult> best =
      FastCorrelativeScanMatcher(scene.grid, blind_options).Match(scene.initial, scene.points, 0.0);
  RC_ASSERT(best.has_value());
  const double resolution = scene.grid.limits().resolution();
  const Eigen::Vector2d best_offset =
      (best->pose.translation() - scene.initial.translation()) / resolution;
  const double radius_cells = options.ambiguity_radius_m / resolution;
  const double threshold = best->score - options.ambiguity_score_margin;
  bool rival = false;
  bool borderline = false;
  ForEachCandidate(scene.grid, scene.initial, scene.points, options.linear_search_window_m,
                   options.angular_search_window_rad, [&](int x, int y, double score) {
                     const double dx = x - std::round(best_offset.x());
                     const double dy = y - std::round(best_offset.y());
                     if (dx * dx + dy * dy <= radius_cells * radius_cells) return;
                     borderline |= std::abs(score - threshold) < 1e-9;
                     rival |= score >= threshold;
                   });
  RC_PRE(!borderline);  // rounding would decide, not the search
  std::optional<ScanMatchResult> ambiguous;
  const std::optional<ScanMatchResult> result =
      FastCorrelativeScanMatcher(scene.grid, options)
          .Match(scene.initial, scene.points, 0.0, options.linear_search_window_m,
                 options.angular_search_window_rad, &ambiguous);
  RC_ASSERT(result.has_value() == !rival);
  RC_ASSERT(ambiguous.has_value() == rival);
  if (rival) RC_ASSERT(ambiguous->pose.translation() == best->pose.translation());
}

TEST(FastCorrelativeScanMatcherTest, FindsScanFarFromInitialEstimateInRoom) {
  const grid::ProbabilityGrid grid = testing::RoomGrid();
  const Rigid2d truth(-0.4, 0.3, 0.2);
  const PointCloud points = testing::ScanPoints(testing::Room(), truth);
  const auto build_start = std::chrono::steady_clock::now();
  const FastCorrelativeScanMatcher matcher(grid, FastCorrelativeScanMatcherOptions{});
  const auto match_start = std::chrono::steady_clock::now();
  // 2.5 m and 0.4 rad away: only a search over the whole window finds it.
  const std::optional<ScanMatchResult> result =
      matcher.Match(Rigid2d(truth.x() + 1.5, truth.y() - 2.0, truth.theta() - 0.4), points, 0.55);
  const auto end = std::chrono::steady_clock::now();
  std::cout << "Precomputation of " << grid.limits().width() << "x" << grid.limits().height()
            << " cells: "
            << std::chrono::duration<double, std::milli>(match_start - build_start).count()
            << " ms; branch-and-bound match of " << points.size() << " points (7 m, 30 deg): "
            << std::chrono::duration<double, std::milli>(end - match_start).count() << " ms\n";
  ASSERT_TRUE(result.has_value());
  EXPECT_LT((result->pose.translation() - truth.translation()).norm(), 0.06) << result->pose;
  EXPECT_LT(std::abs(geometry::NormalizeAngle(result->pose.theta() - truth.theta())), 0.01);
  EXPECT_GT(result->score, 0.7);

  const std::optional<ScanMatchResult> global = matcher.MatchFullSubmap(points, 0.55);
  ASSERT_TRUE(global.has_value());
  EXPECT_LT((global->pose.translation() - truth.translation()).norm(), 0.06) << global->pose;
}

TEST(FastCorrelativeScanMatcherTest, RejectsPoorMatchesAndInvalidOptions) {
  const grid::ProbabilityGrid grid = testing::RoomGrid();
  const FastCorrelativeScanMatcher matcher(grid, FastCorrelativeScanMatcherOptions{});
  // A scan of a different room (a small square) does not match well anywhere.
  std::vector<testing::Segment> other;
  testing::AddBox(-0.7, -0.7, 0.7, 0.7, &other);
  EXPECT_FALSE(matcher.Match(Rigid2d(), testing::ScanPoints(other, Rigid2d()), 0.7).has_value());
  EXPECT_FALSE(matcher.Match(Rigid2d(), {}, 0.0).has_value());
  FastCorrelativeScanMatcherOptions options;
  options.branch_and_bound_depth = 0;
  EXPECT_THROW(FastCorrelativeScanMatcher(grid, options), std::invalid_argument);
}

// Two identical closed rooms side by side: a scan from inside one fits the
// other just as well, the perceptual aliasing of periodic buildings.
TEST(FastCorrelativeScanMatcherTest, RejectsAmbiguousMatchesWhenAskedTo) {
  std::vector<testing::Segment> walls;
  testing::AddBox(-3.0, -1.2, -0.6, 1.3, &walls);
  testing::AddBox(0.6, -1.2, 3.0, 1.3, &walls);
  testing::AddBox(-2.2, 0.2, -1.9, 0.6, &walls);  // a cupboard in each room
  testing::AddBox(1.4, 0.2, 1.7, 0.6, &walls);
  grid::ProbabilityGrid grid(grid::MapLimits(0.05, {-3.5, -1.7}, 140, 60));
  const grid::RangeDataInserter inserter({});
  for (const double x : {-1.6, -1.2, 2.0, 2.4}) {
    const Rigid2d pose(x, -0.4, 0.0);
    const sensor::RangeData data = sensor::ToRangeData(testing::CastScan(walls, pose), {});
    inserter.Insert(pose.translation(), TransformPointCloud(data.returns, pose),
                    TransformPointCloud(data.misses, pose), &grid);
  }
  const Rigid2d truth(-1.4, -0.5, 0.0);
  const PointCloud points = testing::ScanPoints(walls, truth);
  FastCorrelativeScanMatcherOptions options;
  options.ambiguity_radius_m = 0.0;
  const std::optional<ScanMatchResult> blind =
      FastCorrelativeScanMatcher(grid, options).Match(truth, points, 0.55);
  ASSERT_TRUE(blind.has_value());  // one of the two rooms
  options.ambiguity_radius_m = 0.3;
  options.ambiguity_score_margin = 0.05;
  EXPECT_FALSE(FastCorrelativeScanMatcher(grid, options).Match(truth, points, 0.55).has_value());
  // The caller can tell that from no match at all (the loop-closure counts).
  const FastCorrelativeScanMatcher matcher(grid, options);
  std::optional<ScanMatchResult> ambiguous;
  EXPECT_FALSE(matcher
                   .Match(truth, points, 0.55, options.linear_search_window_m,
                          options.angular_search_window_rad, &ambiguous)
                   .has_value());
  ASSERT_TRUE(ambiguous.has_value());
  // The best of the ambiguous search is still told: one of the two rooms,
  // scoring as the blind matcher's answer does.
  EXPECT_DOUBLE_EQ(ambiguous->score, blind->score);
  EXPECT_EQ(ambiguous->pose.translation(), blind->pose.translation());
  std::optional<ScanMatchResult> unmatched_ambiguous;
  EXPECT_FALSE(matcher
                   .Match(truth, points, 0.99, options.linear_search_window_m,
                          options.angular_search_window_rad, &unmatched_ambiguous)
                   .has_value());
  EXPECT_FALSE(unmatched_ambiguous.has_value());  // nothing scores 0.99: no match, not ambiguous
  // A window too small to reach the other room leaves nothing to confuse.
  std::optional<ScanMatchResult> near_ambiguous;
  const std::optional<ScanMatchResult> near =
      matcher.Match(truth, points, 0.55, 1.0, 0.5, &near_ambiguous);
  EXPECT_FALSE(near_ambiguous.has_value());
  ASSERT_TRUE(near.has_value());
  EXPECT_LT((near->pose.translation() - truth.translation()).norm(), 0.06) << near->pose;
}

}  // namespace
}  // namespace scout::slam
