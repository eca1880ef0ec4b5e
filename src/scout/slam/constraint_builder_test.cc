#include "scout/slam/constraint_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include "scout/slam/fast_correlative_scan_matcher.h"
#include "scout/slam/global_test_world.h"

namespace scout::slam {
namespace {

using geometry::Rigid2d;
using global_testing::Wall;

// A finished submap of the bottom corridor built from 36 scans (a real
// submap holds ~70, so its walls are confidently occupied), in a frame rotated
// and shifted against the world so frame mistakes show.
struct SubmapScene {
  std::vector<Wall> walls = global_testing::CorridorLoop();
  Rigid2d submap_frame{-6.0, -4.5, 0.3};
  std::shared_ptr<const grid::ProbabilityGrid> grid;

  SubmapScene() {
    std::vector<Rigid2d> poses;
    for (int i = 0; i < 36; ++i) {
      poses.emplace_back(-8.5 + 0.25 * i, -4.5 + 0.1 * std::sin(i), 0.05 * std::cos(i));
    }
    grid = std::make_shared<const grid::ProbabilityGrid>(
        global_testing::BuildGrid(walls, submap_frame, poses));
  }
};

TEST(ConstraintBuilderTest, FindsTheTrueRelativePoseFromAFarOffEstimate) {
  const SubmapScene scene;
  ConstraintBuilder builder({});
  builder.AddFinishedSubmap(0, scene.grid);
  const Rigid2d node_world(-3.7, -4.3, 0.4);
  const Rigid2d truth = scene.submap_frame.inverse() * node_world;
  // 1.4 m and 14 degrees off: far beyond local scan matching, inside 7 m / 30 deg.
  const Rigid2d estimate = truth * Rigid2d(1.2, -0.7, 0.25);
  const std::optional<Constraint> c =
      builder.Search(0, 17, estimate, global_testing::ScanReturns(scene.walls, node_world),
                     /*travel_m=*/100.0);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->submap_id, 0);
  EXPECT_EQ(c->node_id, 17);
  EXPECT_EQ(c->kind, ConstraintKind::kInterSubmap);
  EXPECT_EQ(c->translation_weight, 1.1e4);
  EXPECT_EQ(c->rotation_weight, 1e5);
  EXPECT_LT((c->relative_pose.translation() - truth.translation()).norm(), 0.02);
  EXPECT_LT(std::abs(geometry::NormalizeAngle(c->relative_pose.theta() - truth.theta())), 0.01);
  EXPECT_EQ(builder.num_searches(), 1);
  EXPECT_EQ(builder.num_constraints_found(), 1);
}

TEST(ConstraintBuilderTest, RejectsAScanOfAnotherPlace) {
  const SubmapScene scene;
  ConstraintBuilder builder({});
  builder.AddFinishedSubmap(0, scene.grid);
  // A round room of radius 1.2 m: nothing like the straight corridor.
  std::vector<Wall> round_room;
  for (int k = 0; k < 24; ++k) {
    const double a = 2.0 * M_PI * k / 24, b = 2.0 * M_PI * (k + 1) / 24;
    round_room.push_back({1.2 * Eigen::Vector2d(std::cos(a), std::sin(a)),
                          1.2 * Eigen::Vector2d(std::cos(b), std::sin(b))});
  }
  const Rigid2d estimate = scene.submap_frame.inverse() * Rigid2d(-3.0, -4.5, 0.0);
  EXPECT_FALSE(
      builder.Search(0, 3, estimate, global_testing::ScanReturns(round_room, Rigid2d()), 100.0)
          .has_value());
  EXPECT_EQ(builder.num_searches(), 1);
  EXPECT_EQ(builder.num_constraints_found(), 0);
  // Nothing scored above the minimum: no match, rather than an ambiguous one.
  EXPECT_EQ(builder.num_without_match(), 1);
  EXPECT_EQ(builder.num_ambiguous(), 0);
}

TEST(ConstraintBuilderTest, SamplesAFixedRatioOfNearbyPairsPerSubmap) {
  const SubmapScene scene;
  ConstraintBuilderOptions options;
  options.sampling_ratio = 0.3;
  options.min_overlap = 0.0;  // the sampler alone
  ConstraintBuilder builder(options);
  const PointCloud points = global_testing::ScanReturns(scene.walls, Rigid2d(-5.0, -4.5, 0.0));
  EXPECT_FALSE(builder.ShouldSearch(0, Rigid2d(), points, 0.0));  // not finished yet
  builder.AddFinishedSubmap(0, scene.grid);
  builder.AddFinishedSubmap(1, scene.grid);
  // Far pairs are never searched and do not advance the sampler.
  for (int i = 0; i < 5; ++i) {
    EXPECT_FALSE(builder.ShouldSearch(0, Rigid2d(15.5, 0.0, 0.0), points, 0.0));
  }
  int searched = 0;
  for (int i = 0; i < 100; ++i)
    searched += builder.ShouldSearch(0, Rigid2d(14.0, 3.0, 0.0), points, 0.0);
  EXPECT_EQ(searched, 30);
  // Each submap samples on its own: its first eligible pair is searched.
  EXPECT_TRUE(builder.ShouldSearch(1, Rigid2d(1.0, 0.0, 0.0), points, 0.0));
}

TEST(ConstraintBuilderTest, SearchesAtLeastOncePerSampleSpacingOfTravel) {
  const SubmapScene scene;
  ConstraintBuilderOptions options;
  options.sampling_ratio = 0.05;
  options.max_sample_spacing_m = 4.0;
  options.min_overlap = 0.0;
  ConstraintBuilder spaced(options);
  options.max_sample_spacing_m = 0.0;
  ConstraintBuilder ratio_only(options);
  const PointCloud points = global_testing::ScanReturns(scene.walls, Rigid2d(-5.0, -4.5, 0.0));
  spaced.AddFinishedSubmap(0, scene.grid);
  ratio_only.AddFinishedSubmap(0, scene.grid);
  // 100 nodes one metre apart (a sparse log): the ratio alone searches 5 of
  // them, 20 m apart; the spacing searches every 4 m.
  std::vector<int> searched_spaced, searched_ratio;
  for (int i = 0; i < 100; ++i) {
    if (spaced.ShouldSearch(0, Rigid2d(1.0, 0.0, 0.0), points, 1.0 * i)) {
      searched_spaced.push_back(i);
    }
    if (ratio_only.ShouldSearch(0, Rigid2d(1.0, 0.0, 0.0), points, 1.0 * i)) {
      searched_ratio.push_back(i);
    }
  }
  EXPECT_EQ(searched_ratio, (std::vector<int>{0, 20, 40, 60, 80}));
  ASSERT_EQ(searched_spaced.size(), 25u);
  for (size_t k = 0; k < searched_spaced.size(); ++k) EXPECT_EQ(searched_spaced[k], 4 * int(k));
  options.max_sample_spacing_m = -1.0;
  EXPECT_THROW(ConstraintBuilder{options}, std::invalid_argument);
}

TEST(ConstraintBuilderTest, SearchesOnlyPairsWhoseScanOverlapsTheSubmap) {
  const SubmapScene scene;
  ConstraintBuilderOptions options;
  options.sampling_ratio = 1.0;
  ConstraintBuilder builder(options);
  builder.AddFinishedSubmap(0, scene.grid);
  const Rigid2d node_world(-5.0, -4.4, 0.1);
  const PointCloud points = global_testing::ScanReturns(scene.walls, node_world);
  const Rigid2d in_submap = scene.submap_frame.inverse() * node_world;
  EXPECT_GT(ObservedFraction(*scene.grid, in_submap, points), 0.9);
  EXPECT_TRUE(builder.ShouldSearch(0, in_submap, points, 0.0));
  // The same scan believed 10 m away, where the submap has seen nothing.
  const Rigid2d elsewhere = in_submap * Rigid2d(0.0, 10.0, 0.0);
  EXPECT_LT(ObservedFraction(*scene.grid, elsewhere, points), 0.05);
  EXPECT_FALSE(builder.ShouldSearch(0, elsewhere, points, 0.0));
  EXPECT_EQ(builder.num_without_overlap(), 1);
  // Three points fit somewhere in any submap: too few to search at all.
  const PointCloud three(points.begin(), points.begin() + 3);
  EXPECT_FALSE(builder.ShouldSearch(0, in_submap, three, 0.0));
}

TEST(ConstraintBuilderTest, RaysThroughKnownWallsMeanTheWrongPlace) {
  const SubmapScene scene;
  const Rigid2d node_world(-5.0, -4.4, 0.1);
  const PointCloud points = global_testing::ScanReturns(scene.walls, node_world);
  const Rigid2d truth = scene.submap_frame.inverse() * node_world;
  EXPECT_LT(SeeThroughFraction(*scene.grid, truth, points, 0.15), 0.05);
  // Turned by 90 degrees in place, the rays along the corridor now cross
  // its walls.
  EXPECT_GT(SeeThroughFraction(*scene.grid, truth * Rigid2d(0.0, 0.0, M_PI / 2), points, 0.15),
            0.3);
}

TEST(ConstraintBuilderTest, SearchWindowGrowsWithTheTrajectoryBetween) {
  ConstraintBuilderOptions options;
  options.min_search_window_m = 1.0;
  options.search_window_per_travel = 0.02;
  options.fast_correlative_scan_matcher.linear_search_window_m = 7.0;
  const ConstraintBuilder builder(options);
  EXPECT_DOUBLE_EQ(builder.SearchWindow(0.0), 1.0);
  EXPECT_DOUBLE_EQ(builder.SearchWindow(100.0), 3.0);
  EXPECT_DOUBLE_EQ(builder.SearchWindow(1000.0), 7.0);  // capped
  options.search_window_per_travel = 0.0;
  EXPECT_DOUBLE_EQ(ConstraintBuilder(options).SearchWindow(0.0), 7.0);  // always the full window
  EXPECT_DOUBLE_EQ(ConstraintBuilder(options).AngularSearchWindow(0.0),
                   options.fast_correlative_scan_matcher.angular_search_window_rad);
  options.search_window_per_travel = 0.02;
  options.min_angular_search_window_deg = 5.0;
  options.angular_search_window_deg_per_m = 0.1;
  EXPECT_NEAR(ConstraintBuilder(options).AngularSearchWindow(100.0), 15.0 * M_PI / 180.0, 1e-12);
  EXPECT_NEAR(ConstraintBuilder(options).AngularSearchWindow(1000.0),
              options.fast_correlative_scan_matcher.angular_search_window_rad, 1e-12);
}

// A submap built from three scans a metre apart holds walls hit once or twice
// (p 0.55 to 0.6): its own scans score about 0.6 in it, and a true match of
// a fourth scan scores below min_score. Relative to its own scans it is
// found; a submap of 36 scans keeps min_score and the ambiguity margin.
TEST(ConstraintBuilderTest, ThinSubmapsAcceptMatchesRelativeToTheirOwnScans) {
  const SubmapScene dense;
  const std::vector<Rigid2d> thin_poses = {{-8.5, -4.5, 0.0}, {-7.0, -4.4, 0.05}};
  const auto thin_grid = std::make_shared<const grid::ProbabilityGrid>(
      global_testing::BuildGrid(dense.walls, dense.submap_frame, thin_poses));
  std::vector<SubmapScan> own_scans;
  for (const Rigid2d& pose : thin_poses) {
    own_scans.push_back(
        {dense.submap_frame.inverse() * pose,
         std::make_shared<const PointCloud>(global_testing::ScanReturns(dense.walls, pose))});
  }
  double own_score = 0.0;
  size_t own_points = 0;
  for (const SubmapScan& scan : own_scans) {
    own_score += MatchScore(*thin_grid, scan.pose_in_submap, *scan.points) * scan.points->size();
    own_points += scan.points->size();
  }
  own_score /= static_cast<double>(own_points);
  EXPECT_LT(own_score, 0.65);

  ConstraintBuilderOptions options;
  options.min_score_fraction_of_own_scans = 0.8;
  ConstraintBuilder relative(options);
  relative.AddFinishedSubmap(0, thin_grid, own_scans);
  relative.AddFinishedSubmap(1, dense.grid, own_scans);
  EXPECT_NEAR(relative.MinScore(0), 0.8 * own_score, 1e-9);
  EXPECT_EQ(relative.MinScore(1), options.min_score);
  // Its ambiguity margin shrinks by how far its walls stand out from 0.5.
  EXPECT_NEAR(relative.AmbiguityScoreMargin(0), 0.05 * (own_score - 0.5) / (0.55 / 0.8 - 0.5),
              1e-9);
  EXPECT_EQ(relative.AmbiguityScoreMargin(1), 0.05);
  ConstraintBuilderOptions fixed_options;
  fixed_options.min_score_fraction_of_own_scans = 0.0;
  ConstraintBuilder fixed(fixed_options);
  fixed.AddFinishedSubmap(0, thin_grid, own_scans);
  EXPECT_EQ(fixed.MinScore(0), 0.55);
  EXPECT_EQ(fixed.AmbiguityScoreMargin(0), 0.05);

  const Rigid2d node_world(-6.0, -4.6, 0.1);
  const Rigid2d truth = dense.submap_frame.inverse() * node_world;
  const PointCloud points = global_testing::ScanReturns(dense.walls, node_world);
  const double true_score = MatchScore(*thin_grid, truth, points);
  EXPECT_LT(true_score, 0.55) << own_score;
  EXPECT_GT(true_score, relative.MinScore(0));
  const Rigid2d estimate = truth * Rigid2d(0.3, -0.2, 0.05);
  EXPECT_FALSE(fixed.Search(0, 9, estimate, points, 10.0).has_value());
  const std::optional<Constraint> found = relative.Search(0, 9, estimate, points, 10.0);
  ASSERT_TRUE(found.has_value());
  EXPECT_LT((found->relative_pose.translation() - truth.translation()).norm(), 0.05);
}

// A 6 m wide hall, 80 m long, whose pillars and wall boxes repeat every 8 m:
// within the lidar's 8 m every place looks like the places 8 m, 16 m, ...
// along it (the museum world's halls of equal exhibits).
std::vector<Wall> RepeatingHall() {
  std::vector<Wall> walls;
  global_testing::AddRectangle({-40.0, -3.0}, {40.0, 3.0}, &walls);
  for (int k = -5; k <= 4; ++k) {
    const double x = 8.0 * k;
    global_testing::AddRectangle({x - 0.2, -1.7}, {x + 0.3, -1.3}, &walls);  // pillars
    global_testing::AddRectangle({x - 0.2, 1.0}, {x + 0.3, 1.4}, &walls);
    global_testing::AddRectangle({x + 1.0, -3.0}, {x + 2.1, -2.6}, &walls);  // wall boxes
    global_testing::AddRectangle({x + 3.0, 2.5}, {x + 3.6, 3.0}, &walls);
    global_testing::AddRectangle({x + 5.2, -3.0}, {x + 6.6, -2.7}, &walls);
    global_testing::AddRectangle({x + 6.1, 2.4}, {x + 6.6, 3.0}, &walls);
  }
  return walls;
}

// The hall's submap, mapped along x = -10 .. 10, and the scan of a robot
// standing at x = 0.
std::pair<std::shared_ptr<const grid::ProbabilityGrid>, PointCloud> RepeatingHallAtItsCentre() {
  const std::vector<Wall> walls = RepeatingHall();
  std::vector<Rigid2d> poses;
  for (int i = 0; i <= 40; ++i) poses.emplace_back(-10.0 + 0.5 * i, 0.1 * std::sin(i), 0.0);
  return {
      std::make_shared<const grid::ProbabilityGrid>(global_testing::BuildGrid(walls, {}, poses)),
      global_testing::ScanReturns(walls, Rigid2d(0.0, 0.0, 0.0))};
}

// The robot stands at x = 0; drift put it at x = 5.2. The search window
// (1 m + 2 % of 125 m = 3.5 m) reaches the copy of its place at x = 8 but not
// x = 0, so the match lands 8 m off. Searching again around that match, three
// times its distance from the estimate (8.4 m), reaches x = 0 and x = 16,
// which look the same: the match is no longer the one best, and is rejected.
TEST(ConstraintBuilderTest, AMatchFarFromTheEstimateMustStayUniqueInAWiderWindow) {
  const auto [grid, scan] = RepeatingHallAtItsCentre();
  const Rigid2d estimate(5.2, 0.15, 0.02);
  ConstraintBuilderOptions options;
  options.min_overlap = 0.0;
  options.wide_ambiguity_min_innovation_m = 0.0;  // off
  ConstraintBuilder narrow(options);
  narrow.AddFinishedSubmap(0, grid);
  const std::optional<Constraint> alias = narrow.Search(0, 1, estimate, scan, 125.0);
  ASSERT_TRUE(alias.has_value());  // without the wide test: the copy, 8 m off
  EXPECT_NEAR(alias->relative_pose.x(), 8.0, 0.1);

  options.wide_ambiguity_min_innovation_m = 2.0;  // the defaults
  options.wide_ambiguity_window_factor = 3.0;
  ConstraintBuilder wide(options);
  wide.AddFinishedSubmap(0, grid);
  EXPECT_FALSE(wide.Search(0, 1, estimate, scan, 125.0).has_value());
  EXPECT_EQ(wide.num_wide_ambiguous(), 1);
  // A window of twice the distance (5.6 m) does not reach back to x = 0.
  options.wide_ambiguity_window_factor = 2.0;
  ConstraintBuilder twice(options);
  twice.AddFinishedSubmap(0, grid);
  EXPECT_TRUE(twice.Search(0, 1, estimate, scan, 125.0).has_value());
}

// The pose graph's gate: once loop closures tie the node to the submap, the
// estimate is known within the window of that chain, and the copy 2.8 m
// from the estimate above is rejected however well it scores.
TEST(ConstraintBuilderTest, AMatchFartherFromTheEstimateThanTheGateIsRejected) {
  const auto [grid, scan] = RepeatingHallAtItsCentre();
  const Rigid2d estimate(5.2, 0.15, 0.02);
  ConstraintBuilderOptions options;
  options.min_overlap = 0.0;
  options.wide_ambiguity_min_innovation_m = 0.0;
  ConstraintBuilder builder(options);
  builder.AddFinishedSubmap(0, grid);
  EXPECT_FALSE(builder.Search(0, 1, estimate, scan, 125.0, /*max_innovation_m=*/2.5).has_value());
  EXPECT_EQ(builder.num_gated(), 1);
  const std::optional<Constraint> loose = builder.Search(0, 1, estimate, scan, 125.0, 3.0);
  ASSERT_TRUE(loose.has_value());
  EXPECT_NEAR(loose->relative_pose.x(), 8.0, 0.1);
  EXPECT_EQ(builder.num_gated(), 1);
}

// Where the place has no copy, a match far from the estimate survives the
// wide test and is the true pose.
TEST(ConstraintBuilderTest, AUniqueMatchFarFromTheEstimatePassesTheWideTest) {
  const SubmapScene scene;
  ConstraintBuilderOptions options;
  options.wide_ambiguity_min_innovation_m = 2.0;
  options.wide_ambiguity_window_factor = 3.0;
  ConstraintBuilder builder(options);
  builder.AddFinishedSubmap(0, scene.grid);
  const Rigid2d node_world(-4.0, -4.4, 0.1);
  const Rigid2d truth = scene.submap_frame.inverse() * node_world;
  const Rigid2d estimate = truth * Rigid2d(2.4, 0.5, 0.05);  // 2.45 m off
  const std::optional<Constraint> c = builder.Search(
      0, 5, estimate, global_testing::ScanReturns(scene.walls, node_world), /*travel_m=*/100.0);
  ASSERT_TRUE(c.has_value());
  EXPECT_LT((c->relative_pose.translation() - truth.translation()).norm(), 0.05);
  EXPECT_EQ(builder.num_wide_ambiguous(), 0);
}

// A revisit scoring a little below the minimum score is taken where its best
// pose lands near the estimate, and not where it lands far from it.
TEST(ConstraintBuilderTest, AMatchBelowTheMinimumScoreIsKeptOnlyNearTheEstimate) {
  const SubmapScene scene;
  const Rigid2d node_world(-3.7, -4.3, 0.4);
  const Rigid2d truth = scene.submap_frame.inverse() * node_world;
  const PointCloud scan = global_testing::ScanReturns(scene.walls, node_world);
  const FastCorrelativeScanMatcher scorer(scene.grid, FastCorrelativeScanMatcherOptions{});
  const std::optional<ScanMatchResult> at_truth = scorer.Match(truth, scan, 0.0, 0.1, 0.02);
  ASSERT_TRUE(at_truth.has_value());
  ConstraintBuilderOptions options;
  options.min_score_fraction_of_own_scans = 0.0;  // one minimum score for the submap
  options.min_score = at_truth->score / 0.9;      // the revisit scores 0.9 of it
  options.near_match_min_score_fraction = 0.75;
  const Rigid2d near_estimate = truth * Rigid2d(0.15, -0.1, 0.03);
  const Rigid2d far_estimate = truth * Rigid2d(1.0, -0.6, 0.03);

  options.near_match_max_innovation_m = 0.0;  // off
  ConstraintBuilder off(options);
  off.AddFinishedSubmap(0, scene.grid);
  EXPECT_FALSE(off.Search(0, 1, near_estimate, scan, /*travel_m=*/100.0).has_value());
  EXPECT_EQ(off.num_without_match(), 1);

  options.near_match_max_innovation_m = 0.3;
  ConstraintBuilder on(options);
  on.AddFinishedSubmap(0, scene.grid);
  const std::optional<Constraint> c = on.Search(0, 1, near_estimate, scan, 100.0);
  ASSERT_TRUE(c.has_value());
  EXPECT_LT((c->relative_pose.translation() - truth.translation()).norm(), 0.05);
  EXPECT_EQ(on.num_near_matches(), 1);
  // The same revisit from an estimate 1.2 m off (inside the 3 m window): the
  // match is right, but a low score that far from the estimate is not enough.
  EXPECT_FALSE(on.Search(0, 2, far_estimate, scan, 100.0).has_value());
  EXPECT_EQ(on.num_without_match(), 1);
  EXPECT_EQ(on.num_constraints_found(), 1);

  // Scoring above the minimum, the far match is taken, and is not a near match.
  options.min_score = 0.95 * at_truth->score;
  ConstraintBuilder above(options);
  above.AddFinishedSubmap(0, scene.grid);
  const std::optional<Constraint> far = above.Search(0, 2, far_estimate, scan, 100.0);
  ASSERT_TRUE(far.has_value());
  EXPECT_LT((far->relative_pose.translation() - truth.translation()).norm(), 0.05);
  EXPECT_EQ(above.num_near_matches(), 0);
}

TEST(ConstraintBuilderTest, FixedRatioSamplerIsDeterministic) {
  FixedRatioSampler a(0.3), b(0.3);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(a.Pulse(), b.Pulse());
  FixedRatioSampler all(1.0);
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(all.Pulse());
}

TEST(ConstraintBuilderTest, SamplingPhaseShiftsThePicksButKeepsTheRatio) {
  const auto picks = [](double phase) {
    FixedRatioSampler sampler(0.1, phase);
    std::vector<int> at;
    for (int i = 1; i <= 1000; ++i) {
      if (sampler.Pulse()) at.push_back(i);
    }
    return at;
  };
  const std::vector<int> none = picks(0.0), half = picks(0.5), most = picks(0.95);
  // Phase 0 is Cartographer's sampler: the first call says yes, then every
  // tenth.
  ASSERT_EQ(none.size(), 100u);
  EXPECT_EQ(none[0], 1);
  EXPECT_EQ(none[1], 11);
  // A phase delays the first yes by phase / ratio calls, and every later one
  // alike; over many calls the fraction stays the ratio.
  ASSERT_GE(half.size(), 99u);
  EXPECT_EQ(half[0], 6);
  EXPECT_EQ(half[1], 16);
  EXPECT_EQ(most[0], 10);
  EXPECT_NEAR(static_cast<double>(most.size()), 100.0, 1.0);
  FixedRatioSampler all(1.0, 0.9);
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(all.Pulse());

  ConstraintBuilderOptions options;
  options.sampling_phase = 1.0;
  EXPECT_THROW(ConstraintBuilder{options}, std::invalid_argument);
  options.sampling_phase = -0.1;
  EXPECT_THROW(ConstraintBuilder{options}, std::invalid_argument);
}

TEST(ConstraintBuilderTest, RejectsBadOptionsAndUnknownSubmaps) {
  ConstraintBuilderOptions options;
  options.sampling_ratio = 0.0;
  EXPECT_THROW(ConstraintBuilder{options}, std::invalid_argument);
  options = {};
  options.min_score = 1.5;
  EXPECT_THROW(ConstraintBuilder{options}, std::invalid_argument);
  options = {};
  options.min_score_fraction_of_own_scans = -0.1;
  EXPECT_THROW(ConstraintBuilder{options}, std::invalid_argument);
  options = {};
  options.fast_correlative_scan_matcher.branch_and_bound_depth = 0;
  EXPECT_THROW(ConstraintBuilder{options}, std::invalid_argument);
  options = {};
  options.wide_ambiguity_min_innovation_m = std::nan("");
  EXPECT_THROW(ConstraintBuilder{options}, std::invalid_argument);
  options = {};
  options.wide_ambiguity_window_factor = 0.0;
  EXPECT_THROW(ConstraintBuilder{options}, std::invalid_argument);
  options = {};
  options.near_match_max_innovation_m = -0.1;
  EXPECT_THROW(ConstraintBuilder{options}, std::invalid_argument);
  options = {};
  options.near_match_min_score_fraction = 1.2;
  EXPECT_THROW(ConstraintBuilder{options}, std::invalid_argument);
  ConstraintBuilder builder({});
  EXPECT_THROW(builder.Search(4, 0, Rigid2d(), {Eigen::Vector2d(1.0, 0.0)}, 0.0),
               std::invalid_argument);
}

}  // namespace
}  // namespace scout::slam
