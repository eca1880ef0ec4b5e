#include "scout/synthetic/correction_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scout/common/error.h"

namespace scout::synthetic {
namespace {

using geometry::Rigid2d;

CorrectionModelOptions Noiseless() {
  CorrectionModelOptions options;
  options.drift_translation_m_per_sqrt_m = 0.0;
  options.drift_heading_rad_per_sqrt_m = 0.0;
  options.drift_heading_rad_per_sqrt_rad = 0.0;
  options.newest_jitter_m = 0.0;
  options.newest_jitter_rad = 0.0;
  options.loop_closure_error_m = 0.0;
  options.loop_closure_error_rad = 0.0;
  return options;
}

// Drives 'model' straight ahead from 'from' in steps of 'step_m'; returns the end pose.
Rigid2d Drive(CorrectionModel* model, const Rigid2d& from, double distance_m, double step_m) {
  Rigid2d pose = from;
  for (double driven = 0.0; driven + 1e-9 < distance_m; driven += step_m) {
    const Rigid2d next = pose * Rigid2d(step_m, 0.0, 0.0);
    model->Move(pose, next);
    pose = next;
  }
  return pose;
}

double PositionError(const Rigid2d& estimate, const Rigid2d& truth) {
  return (estimate.translation() - truth.translation()).norm();
}

TEST(CorrectionModel, WithoutNoiseEstimatesAreExact) {
  CorrectionModel model(Noiseless(), 1);
  Rigid2d pose(1.0, 2.0, 0.3);
  std::vector<Rigid2d> truth;
  for (int i = 0; i < 20; ++i) {
    truth.push_back(pose);
    const Rigid2d local = model.AddSubmap(pose, 2.0 * i);
    EXPECT_LT(PositionError(local, pose), 1e-9);
    model.AddScan(pose.translation(), 2.0 * i, {i});
    if (i % 3 == 2) model.Optimize();
    pose = Drive(&model, pose, 2.0, 0.2);
  }
  for (size_t i = 0; i < truth.size(); ++i) {
    EXPECT_LT(PositionError(model.global_poses()[i], truth[i]), 1e-9);
  }
}

TEST(CorrectionModel, LocalDriftGrowsLikeARandomWalkWithDistance) {
  double sum_sq_10 = 0.0, sum_sq_40 = 0.0, sum_sq_heading = 0.0;
  const int runs = 200;
  for (int seed = 0; seed < runs; ++seed) {
    CorrectionModel model(CorrectionModelOptions{}, seed);
    const Rigid2d at_10 = Drive(&model, Rigid2d(), 10.0, 0.2);
    const Rigid2d local_10 = model.AddSubmap(at_10, 10.0);
    const Rigid2d at_40 = Drive(&model, at_10, 30.0, 0.2);
    const Rigid2d local_40 = model.AddSubmap(at_40, 40.0);
    sum_sq_10 += std::pow(PositionError(local_10, at_10), 2);
    sum_sq_40 += std::pow(PositionError(local_40, at_40), 2);
    sum_sq_heading += std::pow(local_10.theta() - at_10.theta(), 2);
  }
  const double rms_10 = std::sqrt(sum_sq_10 / runs);
  const double rms_40 = std::sqrt(sum_sq_40 / runs);
  const double rms_heading_deg = std::sqrt(sum_sq_heading / runs) * 180.0 / std::numbers::pi;
  // About 1 % of 10 m and 0.5 degree per 10 m (see CorrectionModelOptions).
  EXPECT_GT(rms_10, 0.08);
  EXPECT_LT(rms_10, 0.2);
  EXPECT_GT(rms_heading_deg, 0.35);
  EXPECT_LT(rms_heading_deg, 0.7);
  EXPECT_GT(rms_40, 1.5 * rms_10);
}

// Drives a 20 m square loop with a submap every 2 m, recording whether each
// solve closed a loop; returns the true submap poses.
std::vector<Rigid2d> DriveSquareLoop(CorrectionModel* model, std::vector<bool>* closed) {
  std::vector<Rigid2d> truth;
  Rigid2d pose;
  double travelled = 0.0;
  for (int side = 0; side < 4; ++side) {
    for (int i = 0; i < 10; ++i) {
      truth.push_back(pose);
      model->AddSubmap(pose, travelled);
      const int id = static_cast<int>(truth.size()) - 1;
      model->AddScan(pose.translation(), travelled, {id});
      // Solve along the first three sides only: the last side drifts freely.
      if (id < 30) closed->push_back(model->Optimize());
      pose = Drive(model, pose, 2.0, 0.2);
      travelled += 2.0;
    }
    const Rigid2d turned = pose * Rigid2d(0.0, 0.0, std::numbers::pi / 2);
    model->Move(pose, turned);
    pose = turned;
  }
  // Back at the start.
  truth.push_back(pose);
  model->AddSubmap(pose, travelled);
  model->AddScan(pose.translation(), travelled, {static_cast<int>(truth.size()) - 1});
  return truth;
}

TEST(CorrectionModel, ReturningToAnOldSubmapClosesTheLoop) {
  CorrectionModelOptions options;
  options.newest_pull_fraction = 0.0;  // isolate the loop closure
  options.newest_jitter_m = 0.0;
  options.newest_jitter_rad = 0.0;
  CorrectionModel model(options, 7);
  std::vector<bool> closed;
  const std::vector<Rigid2d> truth = DriveSquareLoop(&model, &closed);
  for (bool c : closed) EXPECT_FALSE(c);
  const std::vector<Rigid2d> before = model.global_poses();
  ASSERT_TRUE(model.Optimize());
  const std::vector<Rigid2d>& after = model.global_poses();
  const int newest = static_cast<int>(truth.size()) - 1;
  // The drift of the loop was visible before and is gone at its end.
  EXPECT_GT(PositionError(before[newest], truth[newest]), 0.05);
  EXPECT_LT(PositionError(after[newest], truth[newest]), 0.05);
  // The oldest submap stays put; those in between move towards the truth.
  EXPECT_EQ(after[0].translation(), before[0].translation());
  for (int id = 1; id < newest; ++id) {
    EXPECT_LE(PositionError(after[id], truth[id]), PositionError(before[id], truth[id]) + 0.03);
  }
}

TEST(CorrectionModel, SolvesMoveRecentSubmapsMostAndOldOnesNotAtAll) {
  CorrectionModel model(CorrectionModelOptions{}, 3);
  Rigid2d pose;
  for (int i = 0; i < 40; ++i) {
    model.AddSubmap(pose, 2.0 * i);
    model.AddScan(pose.translation(), 2.0 * i, {i});
    pose = Drive(&model, pose, 2.0, 0.2);
  }
  const std::vector<Rigid2d> before = model.global_poses();
  EXPECT_FALSE(model.Optimize());  // a straight line closes no loop
  const std::vector<Rigid2d>& after = model.global_poses();
  const auto moved = [&](int id) { return PositionError(after[id], before[id]); };
  EXPECT_GT(moved(39), 0.001);
  for (int id = 0; id < 20; ++id) EXPECT_EQ(moved(id), 0.0) << id;
  EXPECT_GT(moved(39), moved(33));
}

TEST(CorrectionModel, RejectsInvalidOptions) {
  CorrectionModelOptions options;
  options.newest_pull_fraction = 1.5;
  EXPECT_THROW(CorrectionModel(options, 1), InputError);
}

}  // namespace
}  // namespace scout::synthetic
