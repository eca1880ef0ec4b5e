#include "scout/slam/constraint_builder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

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
      builder.Search(0, 17, estimate, global_testing::ScanReturns(scene.walls, node_world));
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
  EXPECT_FALSE(builder.Search(0, 3, estimate, global_testing::ScanReturns(round_room, Rigid2d()))
                   .has_value());
  EXPECT_EQ(builder.num_searches(), 1);
  EXPECT_EQ(builder.num_constraints_found(), 0);
}

TEST(ConstraintBuilderTest, SamplesAFixedRatioOfNearbyPairsPerSubmap) {
  const SubmapScene scene;
  ConstraintBuilderOptions options;
  options.sampling_ratio = 0.3;
  ConstraintBuilder builder(options);
  EXPECT_FALSE(builder.ShouldSearch(0, Rigid2d()));  // not finished yet
  builder.AddFinishedSubmap(0, scene.grid);
  builder.AddFinishedSubmap(1, scene.grid);
  // Far pairs are never searched and do not advance the sampler.
  for (int i = 0; i < 5; ++i) EXPECT_FALSE(builder.ShouldSearch(0, Rigid2d(15.5, 0.0, 0.0)));
  int searched = 0;
  for (int i = 0; i < 100; ++i) searched += builder.ShouldSearch(0, Rigid2d(14.0, 3.0, 0.0));
  EXPECT_EQ(searched, 30);
  // Each submap samples on its own: its first eligible pair is searched.
  EXPECT_TRUE(builder.ShouldSearch(1, Rigid2d(1.0, 0.0, 0.0)));
}

TEST(ConstraintBuilderTest, FixedRatioSamplerIsDeterministic) {
  FixedRatioSampler a(0.3), b(0.3);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(a.Pulse(), b.Pulse());
  FixedRatioSampler all(1.0);
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(all.Pulse());
}

TEST(ConstraintBuilderTest, RejectsBadOptionsAndUnknownSubmaps) {
  ConstraintBuilderOptions options;
  options.sampling_ratio = 0.0;
  EXPECT_THROW(ConstraintBuilder{options}, std::invalid_argument);
  options = {};
  options.min_score = 1.5;
  EXPECT_THROW(ConstraintBuilder{options}, std::invalid_argument);
  options = {};
  options.fast_correlative_scan_matcher.branch_and_bound_depth = 0;
  EXPECT_THROW(ConstraintBuilder{options}, std::invalid_argument);
  ConstraintBuilder builder({});
  EXPECT_THROW(builder.Search(4, 0, Rigid2d(), {Eigen::Vector2d(1.0, 0.0)}), std::invalid_argument);
}

}  // namespace
}  // namespace scout::slam
