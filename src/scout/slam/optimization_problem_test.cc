#include "scout/slam/optimization_problem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace scout::slam {
namespace {

using geometry::Rigid2d;

constexpr double kIntraTranslationWeight = 5e2;
constexpr double kIntraRotationWeight = 1.6e3;
constexpr double kLoopTranslationWeight = 1.1e4;
constexpr double kLoopRotationWeight = 1e5;

// A 10 m square driven counter-clockwise in 1 m steps (40 nodes), local SLAM
// drifting by a heading bias and a scale error per step (about 0.6 m over the
// loop). One submap per 10 nodes, anchored at its first node; each node also
// goes into the previous submap, as local SLAM's two active submaps do. The
// loop closures are what the constraint builder finds when the robot returns:
// the last side against submap 0, and the first side against submap 3.
struct SquareLoop {
  std::vector<Rigid2d> truth;
  std::vector<OptimizationNode> nodes;
  std::vector<Rigid2d> submap_local;
  std::vector<Constraint> constraints;
};

SquareLoop MakeSquareLoop() {
  SquareLoop loop;
  Rigid2d true_pose;
  Rigid2d local_pose;
  for (int i = 0; i < 40; ++i) {
    loop.truth.push_back(true_pose);
    loop.nodes.push_back({static_cast<double>(i), local_pose, local_pose, std::nullopt});
    // Turn 90 degrees after every 10th step.
    const Rigid2d step(1.0, 0.0, (i % 10 == 9) ? M_PI / 2 : 0.0);
    const Rigid2d drifted_step(1.005, 0.0, step.theta() + 0.002);
    true_pose = true_pose * step;
    local_pose = local_pose * drifted_step;
  }
  for (int s = 0; s < 4; ++s) loop.submap_local.push_back(loop.nodes[10 * s].local_pose);
  for (int i = 0; i < 40; ++i) {
    for (int s : {i / 10, i / 10 - 1}) {
      if (s < 0) continue;
      loop.constraints.push_back({s, i, loop.submap_local[s].inverse() * loop.nodes[i].local_pose,
                                  kIntraTranslationWeight, kIntraRotationWeight,
                                  ConstraintKind::kIntraSubmap});
    }
  }
  for (int i = 30; i < 40; ++i) {
    loop.constraints.push_back({0, i, loop.truth[0].inverse() * loop.truth[i],
                                kLoopTranslationWeight, kLoopRotationWeight,
                                ConstraintKind::kInterSubmap});
  }
  for (int i = 0; i < 10; ++i) {
    loop.constraints.push_back({3, i, loop.truth[30].inverse() * loop.truth[i],
                                kLoopTranslationWeight, kLoopRotationWeight,
                                ConstraintKind::kInterSubmap});
  }
  return loop;
}

double RmsTranslationError(const std::vector<Rigid2d>& a, const std::vector<Rigid2d>& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    sum += (a[i].translation() - b[i].translation()).squaredNorm();
  }
  return std::sqrt(sum / a.size());
}

double MaxTranslationError(const std::vector<Rigid2d>& a, const std::vector<Rigid2d>& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, (a[i].translation() - b[i].translation()).norm());
  }
  return worst;
}

TEST(OptimizationProblemTest, ClosingTheLoopRecoversTheSquare) {
  const SquareLoop loop = MakeSquareLoop();
  std::vector<Rigid2d> start;
  for (const auto& n : loop.nodes) start.push_back(n.global_pose);
  const double drift = MaxTranslationError(start, loop.truth);
  const double open_loop_rms = RmsTranslationError(start, loop.truth);
  ASSERT_GT(drift, 0.4);  // the test must start far from the truth

  const OptimizationProblem problem({});
  const OptimizationResult result = problem.Solve(loop.nodes, loop.submap_local, loop.constraints);
  EXPECT_TRUE(result.summary.usable);
  EXPECT_LT(result.summary.final_cost, result.summary.initial_cost);
  ASSERT_EQ(result.node_global_poses.size(), 40u);
  ASSERT_EQ(result.submap_global_poses.size(), 4u);

  // The closed end is where the loop closures say it is.
  for (int i = 36; i < 40; ++i) {
    EXPECT_LT((result.node_global_poses[i].translation() - loop.truth[i].translation()).norm(),
              0.08)
        << "node " << i;
    EXPECT_LT(std::abs(geometry::NormalizeAngle(result.node_global_poses[i].theta() -
                                                loop.truth[i].theta())),
              0.02);
  }
  // The biased drift is spread over the loop, not removed, so the far corner
  // keeps some error; overall it must shrink well below the open-loop error.
  EXPECT_LT(RmsTranslationError(result.node_global_poses, loop.truth), 0.5 * open_loop_rms)
      << "open-loop rms " << open_loop_rms;
  EXPECT_LT(MaxTranslationError(result.node_global_poses, loop.truth), drift);
  // Submap 0 anchors the frame.
  EXPECT_EQ(result.submap_global_poses[0].x(), loop.submap_local[0].x());
  EXPECT_EQ(result.submap_global_poses[0].theta(), loop.submap_local[0].theta());
}

TEST(OptimizationProblemTest, HuberLossMakesOneWrongLoopClosureHarmless) {
  SquareLoop loop = MakeSquareLoop();
  const OptimizationProblem problem({});
  const OptimizationResult clean = problem.Solve(loop.nodes, loop.submap_local, loop.constraints);
  // Perceptual aliasing: the far corner claimed to be 1 m from the start.
  loop.constraints.push_back({0, 20, Rigid2d(1.0, 0.5, 0.3), kLoopTranslationWeight,
                              kLoopRotationWeight, ConstraintKind::kInterSubmap});
  const OptimizationResult with_outlier =
      problem.Solve(loop.nodes, loop.submap_local, loop.constraints);
  // Huber scale 100: the wrong closure bends the map by under 0.1 m (scale
  // 10: under 0.05 m), far less than the 0.3 m the pose graph's outlier test
  // then drops it for.
  EXPECT_LT(MaxTranslationError(with_outlier.node_global_poses, clean.node_global_poses), 0.1);
  EXPECT_LT(MaxTranslationError(with_outlier.submap_global_poses, clean.submap_global_poses), 0.1);

  // The same closure marked as trusted (no robust loss) wrecks the map, which
  // shows the tolerance above is not trivially met.
  loop.constraints.back().kind = ConstraintKind::kIntraSubmap;
  const OptimizationResult trusted = problem.Solve(loop.nodes, loop.submap_local, loop.constraints);
  EXPECT_GT(MaxTranslationError(trusted.node_global_poses, clean.node_global_poses), 0.5);
}

// Aliasing rarely comes alone: consecutive nodes in a corridor repeat the
// same wrong match. After the solve, their residuals give them away (and only
// them), and solving without them recovers the clean map.
TEST(OptimizationProblemTest, ResidualsFlagExactlyTheWrongClosures) {
  SquareLoop loop = MakeSquareLoop();
  const OptimizationProblem problem({});
  const OptimizationResult clean = problem.Solve(loop.nodes, loop.submap_local, loop.constraints);
  EXPECT_TRUE(LoopClosureOutliers(clean, loop.constraints, 0.3, 3.0 * M_PI / 180.0).empty());
  const size_t first_wrong = loop.constraints.size();
  for (int i = 11; i < 30; ++i) {
    // Nodes of the second and third sides claimed 1.5 m further along.
    loop.constraints.push_back(
        {1, i, loop.truth[10].inverse() * loop.truth[i] * Rigid2d(1.5, 0.0, 0.0),
         kLoopTranslationWeight, kLoopRotationWeight, ConstraintKind::kInterSubmap});
  }
  const OptimizationResult damped = problem.Solve(loop.nodes, loop.submap_local, loop.constraints);
  const std::vector<size_t> outliers =
      LoopClosureOutliers(damped, loop.constraints, 0.3, 3.0 * M_PI / 180.0);
  EXPECT_EQ(outliers.size(), loop.constraints.size() - first_wrong);
  for (size_t i : outliers) EXPECT_GE(i, first_wrong) << "a right closure was flagged";
  std::vector<Constraint> kept(loop.constraints.begin(), loop.constraints.begin() + first_wrong);
  const OptimizationResult again = problem.Solve(loop.nodes, loop.submap_local, kept);
  EXPECT_LT(MaxTranslationError(again.node_global_poses, clean.node_global_poses), 1e-6);
}

TEST(OptimizationProblemTest, ResultDoesNotDependOnConstraintOrder) {
  SquareLoop loop = MakeSquareLoop();
  const OptimizationProblem problem({});
  const OptimizationResult a = problem.Solve(loop.nodes, loop.submap_local, loop.constraints);
  std::mt19937 rng(7);
  std::shuffle(loop.constraints.begin(), loop.constraints.end(), rng);
  const OptimizationResult b = problem.Solve(loop.nodes, loop.submap_local, loop.constraints);
  for (size_t i = 0; i < a.node_global_poses.size(); ++i) {
    EXPECT_EQ(a.node_global_poses[i].x(), b.node_global_poses[i].x());
    EXPECT_EQ(a.node_global_poses[i].y(), b.node_global_poses[i].y());
    EXPECT_EQ(a.node_global_poses[i].theta(), b.node_global_poses[i].theta());
  }
}

TEST(OptimizationProblemTest, OdometryConstraintsPullTowardsOdometryWhenEnabled) {
  // Two nodes, one submap: local SLAM says 1 m apart, odometry says 2 m.
  std::vector<OptimizationNode> nodes = {
      {0.0, Rigid2d(), Rigid2d(), Rigid2d()},
      {1.0, Rigid2d(1.0, 0.0, 0.0), Rigid2d(1.0, 0.0, 0.0), Rigid2d(2.0, 0.0, 0.0)}};
  const std::vector<Constraint> constraints = {
      {0, 0, Rigid2d(), 1e5, 1e5, ConstraintKind::kIntraSubmap}};
  OptimizationProblemOptions options;
  const OptimizationResult off =
      OptimizationProblem(options).Solve(nodes, {Rigid2d()}, constraints);
  EXPECT_NEAR(off.node_global_poses[1].x(), 1.0, 1e-6);
  options.use_odometry_constraints = true;
  const OptimizationResult on = OptimizationProblem(options).Solve(nodes, {Rigid2d()}, constraints);
  EXPECT_NEAR(on.node_global_poses[1].x(), 1.5, 1e-3);  // equal weights: halfway
}

TEST(OptimizationProblemTest, AngleResidualWrapsAroundPi) {
  // Measured relative heading +179 deg, estimate starts at -179 deg: the
  // normalised residual is 2 deg, not 358, so the solve converges nearby.
  std::vector<OptimizationNode> nodes = {
      {0.0, Rigid2d(0.0, 0.0, -M_PI + 0.0175), Rigid2d(0.0, 0.0, -M_PI + 0.0175), std::nullopt}};
  const std::vector<Constraint> constraints = {
      {0, 0, Rigid2d(0.0, 0.0, M_PI - 0.0175), 1e3, 1e3, ConstraintKind::kIntraSubmap}};
  const OptimizationResult r = OptimizationProblem({}).Solve(nodes, {Rigid2d()}, constraints);
  EXPECT_NEAR(std::abs(geometry::NormalizeAngle(r.node_global_poses[0].theta() - (M_PI - 0.0175))),
              0.0, 1e-6);
}

TEST(OptimizationProblemTest, RejectsBadOptionsAndIds) {
  OptimizationProblemOptions options;
  options.huber_scale = 0.0;
  EXPECT_THROW(OptimizationProblem{options}, std::invalid_argument);
  options = {};
  options.max_num_iterations = 0;
  try {
    OptimizationProblem problem(options);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_num_iterations"), std::string::npos);
  }
  const std::vector<Constraint> bad = {{1, 0, Rigid2d(), 1, 1, ConstraintKind::kIntraSubmap}};
  EXPECT_THROW(OptimizationProblem({}).Solve({{}}, {Rigid2d()}, bad), std::invalid_argument);
}

}  // namespace
}  // namespace scout::slam
