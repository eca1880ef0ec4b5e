#include "scout/io/trajectory_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace scout::io {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

// Poses every 0.5 s (exact in binary, so time differences are exact).
std::vector<PosePair> StraightLine(int poses) {
  std::vector<PosePair> pairs;
  for (int k = 0; k < poses; ++k) {
    const double t = 0.5 * k;
    pairs.push_back({t, geometry::Rigid2d(t, 0, 0), geometry::Rigid2d(t, 0, 0)});
  }
  return pairs;
}

TEST(AlignRigid2d, RecoversAKnownTransformOnNoiselessData) {
  const geometry::Rigid2d truth(3.5, -1.25, 0.7);
  std::vector<PosePair> pairs;
  for (int k = 0; k < 20; ++k) {
    const geometry::Rigid2d estimate(std::cos(0.4 * k) * k, 0.3 * k * k - 2.0, 0.1 * k);
    pairs.push_back({static_cast<double>(k), estimate, truth * estimate});
  }
  const geometry::Rigid2d aligned = AlignRigid2d(pairs);
  EXPECT_NEAR(aligned.x(), truth.x(), 1e-9);
  EXPECT_NEAR(aligned.y(), truth.y(), 1e-9);
  EXPECT_NEAR(aligned.theta(), truth.theta(), 1e-12);
  const TrajectoryErrors errors = ComputeTrajectoryErrors(pairs);
  EXPECT_EQ(errors.matched, 20);
  EXPECT_NEAR(errors.ate_rmse_m, 0.0, 1e-9);
  EXPECT_NEAR(errors.ate_max_m, 0.0, 1e-9);
  // A global transform does not change relative motion.
  EXPECT_NEAR(errors.rpe_1s_trans_m, 0.0, 1e-9);
  EXPECT_NEAR(errors.rpe_1s_rot_deg, 0.0, 1e-9);
}

TEST(AlignRigid2d, DegenerateInputs) {
  EXPECT_NEAR(AlignRigid2d({}).translation().norm(), 0.0, 0.0);
  const geometry::Rigid2d one =
      AlignRigid2d({{0.0, geometry::Rigid2d(1, 2, 0.3), geometry::Rigid2d(4, 6, -1.0)}});
  EXPECT_NEAR(one.x(), 3.0, 1e-12);
  EXPECT_NEAR(one.y(), 4.0, 1e-12);
  EXPECT_NEAR(one.theta(), 0.0, 1e-12);
}

TEST(ComputeTrajectoryErrors, AteOfAlternatingOffsetsIsTheirSize) {
  // Reference along x at 0..3 m; the estimate is off by +d, -d, -d, +d across
  // the line, which has no mean offset and no net rotation (the offsets times
  // the centred x -1.5, -0.5, 0.5, 1.5 sum to zero), so the best alignment is the
  // identity and every position error is d. The estimate is also moved by an
  // arbitrary transform the alignment must undo.
  const double d = 0.2;
  const double offsets[] = {d, -d, -d, d};
  const geometry::Rigid2d moved(-7.0, 2.0, 2.1);
  std::vector<PosePair> pairs;
  for (int k = 0; k < 4; ++k) {
    const geometry::Rigid2d estimate(k, offsets[k], 0.0);
    pairs.push_back({static_cast<double>(k), moved * estimate, geometry::Rigid2d(k, 0, 0)});
  }
  const TrajectoryErrors errors = ComputeTrajectoryErrors(pairs);
  EXPECT_NEAR(errors.ate_rmse_m, d, 1e-12);
  EXPECT_NEAR(errors.ate_max_m, d, 1e-12);
}

TEST(ComputeTrajectoryErrors, AteOfAScaledSquare) {
  // An estimate 10 % larger than the unit-square reference about its centre:
  // alignment cannot scale, so each corner is off by 0.1 * sqrt(0.5).
  const double corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<PosePair> pairs;
  for (int k = 0; k < 4; ++k) {
    const double x = corners[k][0], y = corners[k][1];
    pairs.push_back({static_cast<double>(k),
                     geometry::Rigid2d(0.5 + 1.1 * (x - 0.5), 0.5 + 1.1 * (y - 0.5), 0),
                     geometry::Rigid2d(x, y, 0)});
  }
  const TrajectoryErrors errors = ComputeTrajectoryErrors(pairs);
  EXPECT_NEAR(errors.ate_rmse_m, 0.1 * std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(errors.ate_max_m, 0.1 * std::sqrt(0.5), 1e-12);
}

TEST(ComputeTrajectoryErrors, RpeOfAConstantHeadingDrift) {
  // The robot turns on the spot by 0.02 rad/s in the estimate but stands
  // still in the reference: every 1 s step is 0.02 rad off, every 10 s step
  // 0.2 rad, with no translation error.
  std::vector<PosePair> pairs = StraightLine(41);  // 0 .. 20 s
  for (PosePair& p : pairs) {
    p.reference = geometry::Rigid2d(1, 1, 0);
    p.estimate = geometry::Rigid2d(1, 1, 0.02 * p.time_s);
  }
  const TrajectoryErrors errors = ComputeTrajectoryErrors(pairs);
  EXPECT_EQ(errors.rpe_1s_pairs, 39);   // t_i = 0 .. 19
  EXPECT_EQ(errors.rpe_10s_pairs, 21);  // t_i = 0 .. 10
  EXPECT_NEAR(errors.rpe_1s_rot_deg, 0.02 * kDegPerRad, 1e-9);
  EXPECT_NEAR(errors.rpe_10s_rot_deg, 0.2 * kDegPerRad, 1e-9);
  // Every step's error is the same, so the mean equals the RMSE.
  EXPECT_NEAR(errors.rpe_10s_rot_mean_deg, 0.2 * kDegPerRad, 1e-9);
  EXPECT_NEAR(errors.rpe_1s_trans_m, 0.0, 1e-12);
  EXPECT_NEAR(errors.ate_rmse_m, 0.0, 1e-12);  // headings do not enter the ATE
}

TEST(ComputeTrajectoryErrors, RpeOfAScaleErrorAndGapsAreSkipped) {
  // The estimate travels 10 % further than the reference at 1 m/s: each
  // dt-step is 0.1 * dt m too long. Poses at 5.5 .. 7.5 s are missing, so
  // the 1 s steps from 4.5 s and 5 s would span 3 s and are skipped.
  std::vector<PosePair> pairs;
  for (PosePair& p : StraightLine(41)) {
    if (p.time_s > 5.0 && p.time_s < 8.0) continue;
    p.estimate = geometry::Rigid2d(1.1 * p.time_s, 0, 0);
    pairs.push_back(p);
  }
  // Shuffle the order: the metric sorts by time itself.
  std::swap(pairs[0], pairs[10]);
  const TrajectoryErrors errors = ComputeTrajectoryErrors(pairs);
  EXPECT_EQ(errors.matched, 36);
  EXPECT_EQ(errors.rpe_1s_pairs, 39 - 5 - 2);
  EXPECT_EQ(errors.rpe_10s_pairs, 21 - 5);
  EXPECT_NEAR(errors.rpe_1s_trans_m, 0.1, 1e-9);
  EXPECT_NEAR(errors.rpe_10s_trans_m, 1.0, 1e-9);
  EXPECT_NEAR(errors.rpe_1s_rot_deg, 0.0, 1e-12);
}

TEST(ComputeTrajectoryErrors, RpeMeanAndRmseOfOneLargeStep) {
  // Poses 1 s apart. Moving at 1 m/s, the estimate's first step is 0.3 m too
  // long and the next two are right: 1 s errors 0.3, 0, 0 m, mean 0.1 m,
  // RMSE 0.3 / sqrt(3) m. Standing still, the estimate turns 0.03 rad in its
  // second step only: mean 0.01 rad, RMSE 0.03 / sqrt(3) rad.
  std::vector<PosePair> moving, turning;
  const double estimate_x[] = {0.0, 1.3, 2.3, 3.3};
  const double estimate_theta[] = {0.0, 0.0, 0.03, 0.03};
  for (int k = 0; k < 4; ++k) {
    moving.push_back({1.0 * k, geometry::Rigid2d(estimate_x[k], 0, 0), geometry::Rigid2d(k, 0, 0)});
    turning.push_back(
        {1.0 * k, geometry::Rigid2d(2, 1, estimate_theta[k]), geometry::Rigid2d(2, 1, 0)});
  }
  const TrajectoryErrors m = ComputeTrajectoryErrors(moving);
  EXPECT_EQ(m.rpe_1s_pairs, 3);
  EXPECT_NEAR(m.rpe_1s_trans_mean_m, 0.1, 1e-12);
  EXPECT_NEAR(m.rpe_1s_trans_m, 0.3 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(m.rpe_1s_rot_mean_deg, 0.0, 1e-12);
  const TrajectoryErrors t = ComputeTrajectoryErrors(turning);
  EXPECT_NEAR(t.rpe_1s_rot_mean_deg, 0.01 * kDegPerRad, 1e-9);
  EXPECT_NEAR(t.rpe_1s_rot_deg, 0.03 / std::sqrt(3.0) * kDegPerRad, 1e-9);
  EXPECT_NEAR(t.rpe_1s_trans_mean_m, 0.0, 1e-12);
  EXPECT_TRUE(std::isnan(t.rpe_10s_rot_mean_deg));  // 3 s of data
}

TEST(ComputeTrajectoryErrors, NothingToAverageIsNaN) {
  const TrajectoryErrors none = ComputeTrajectoryErrors({});
  EXPECT_EQ(none.matched, 0);
  EXPECT_TRUE(std::isnan(none.ate_rmse_m));
  const TrajectoryErrors short_run = ComputeTrajectoryErrors(StraightLine(3));  // 0 .. 1 s
  EXPECT_EQ(short_run.rpe_1s_pairs, 1);
  EXPECT_EQ(short_run.rpe_10s_pairs, 0);
  EXPECT_TRUE(std::isnan(short_run.rpe_10s_trans_m));
}

}  // namespace
}  // namespace scout::io
