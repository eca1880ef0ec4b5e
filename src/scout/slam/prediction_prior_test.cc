// The Ceres scan matcher's prior toward the motion prediction
// (CeresScanMatcherOptions::prediction_translation_weight and
// prediction_max_constrained_fraction).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "scout/grid/range_data_inserter.h"
#include "scout/sensor/laser_scan.h"
#include "scout/slam/ceres_scan_matcher.h"
#include "scout/slam/point_cloud.h"
#include "scout/slam/test_scene.h"

namespace scout::slam {
namespace {

using geometry::Rigid2d;

// A straight corridor 2 m wide, mapped from x = -10 to 40, seen by a
// forward-looking 180 degree lidar of 8 m: its returns constrain y and the
// heading, not x.
struct Corridor {
  std::vector<testing::Segment> walls = {{{-10.0, -1.02}, {40.0, -1.02}},
                                         {{-10.0, 1.03}, {40.0, 1.03}}};
  grid::ProbabilityGrid grid{grid::MapLimits(0.05, {-2.0, -1.5}, 300, 60)};

  Corridor() {
    const grid::RangeDataInserter inserter({});
    for (int i = 0; i < 12; ++i) {
      const Rigid2d pose(0.5 * i, 0.0, 0.0);
      const sensor::RangeData data =
          sensor::ToRangeData(testing::CastScan(walls, pose, 0.0, 360, 8.f), {});
      inserter.Insert(pose.translation(), TransformPointCloud(data.returns, pose), {}, &grid);
    }
  }

  PointCloud ForwardScan(const Rigid2d& pose) const {
    PointCloud points;
    for (const Eigen::Vector2d& p :
         sensor::ToRangeData(testing::CastScan(walls, pose, 0.0, 360, 8.f), {}).returns) {
      if (p.x() >= 0.0) points.push_back(p);
    }
    return points;
  }
};

CeresScanMatcherOptions FieldOptions(double prediction_weight, double max_constrained_fraction) {
  CeresScanMatcherOptions options;
  options.translation_weight = 1.0;
  options.rotation_weight = 1.0;
  options.likelihood_field.sigma_m = 0.06;
  options.prediction_translation_weight = prediction_weight;
  options.prediction_max_constrained_fraction = max_constrained_fraction;
  return options;
}

// A correlative search placed the scan 8 cm down the corridor (its score
// is flat along it); the odometry predicted the true pose. Only the
// prediction can say where along the corridor the robot is.
TEST(PredictionPriorTest, DecidesTheDirectionACorridorLeavesOpen) {
  const Corridor corridor;
  const Rigid2d truth(2.0, 0.1, 0.0);
  const PointCloud points = corridor.ForwardScan(truth);
  const Rigid2d search(truth.x() + 0.08, truth.y() + 0.02, 0.01);
  const Eigen::Vector2d predicted = truth.translation();

  const Rigid2d without =
      CeresScanMatcher(FieldOptions(0.0, 0.0))
          .Match(search.translation(), search, points, corridor.grid, &predicted);
  const Rigid2d along = CeresScanMatcher(FieldOptions(3.0, 0.05))
                            .Match(search.translation(), search, points, corridor.grid, &predicted);
  // Without the prior the pose stays where the search put it along the
  // corridor; across it, the walls pull it back.
  EXPECT_GT(without.x() - truth.x(), 0.06) << without;
  EXPECT_NEAR(without.y(), truth.y(), 0.01) << without;
  // With it, the open direction follows the prediction (weight 3 against
  // the search's prior 1: 9 / 10 of the way).
  EXPECT_LT(std::abs(along.x() - truth.x()), 0.015) << along;
  EXPECT_NEAR(along.y(), truth.y(), 0.01) << along;
}

// In a room the scan constrains every direction: the directional prior
// leaves a wrong prediction (10 cm off each way) out, where the same weight
// in every direction pulls the pose toward it.
TEST(PredictionPriorTest, LeavesDirectionsTheScanConstrainsToTheScan) {
  const grid::ProbabilityGrid grid = testing::RoomGrid();
  const Rigid2d truth(0.3, -0.2, -0.4);
  const PointCloud points = testing::ScanPoints(testing::Room(), truth);
  const Eigen::Vector2d predicted = truth.translation() + Eigen::Vector2d(0.1, -0.1);

  const Rigid2d directional = CeresScanMatcher(FieldOptions(10.0, 0.05))
                                  .Match(truth.translation(), truth, points, grid, &predicted);
  const Rigid2d everywhere = CeresScanMatcher(FieldOptions(10.0, 0.0))
                                 .Match(truth.translation(), truth, points, grid, &predicted);
  EXPECT_LT((directional.translation() - truth.translation()).norm(), 0.005) << directional;
  EXPECT_GT((everywhere.translation() - truth.translation()).norm(), 0.02) << everywhere;
  // Without a prediction neither prior applies.
  const Rigid2d none =
      CeresScanMatcher(FieldOptions(10.0, 0.0)).Match(truth.translation(), truth, points, grid);
  EXPECT_LT((none.translation() - truth.translation()).norm(), 0.005) << none;
}

// The fraction of a scan on walls across each direction: a corridor's
// returns all lie on walls across y, none across x; a room's constrain both.
TEST(PredictionPriorTest, WallNormalInformationSeesTheCorridorsOpenDirection) {
  const Corridor corridor;
  const PointCloud along = corridor.ForwardScan(Rigid2d(2.0, 0.1, 0.0));
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> corridor_eigen(
      WallNormalInformation(along, 0.3));
  EXPECT_LT(corridor_eigen.eigenvalues()(0), 0.01);
  EXPECT_GT(corridor_eigen.eigenvalues()(1), 0.8);
  EXPECT_GT(std::abs(corridor_eigen.eigenvectors().col(0).x()), 0.99);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> room_eigen(
      WallNormalInformation(testing::ScanPoints(testing::Room(), Rigid2d(0.3, -0.2, -0.4)), 0.3));
  EXPECT_GT(room_eigen.eigenvalues()(0), 0.2);
  // Isolated returns lie on no wall.
  EXPECT_EQ(WallNormalInformation({{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}}, 0.3),
            Eigen::Matrix2d::Zero());
  EXPECT_THROW(WallNormalInformation(along, 0.0), std::invalid_argument);
}

TEST(PredictionPriorTest, RejectsInvalidOptions) {
  EXPECT_THROW(CeresScanMatcher{FieldOptions(-1.0, 0.0)}, std::invalid_argument);
  EXPECT_THROW(CeresScanMatcher{FieldOptions(1.0, 1.5)}, std::invalid_argument);
  EXPECT_THROW(CeresScanMatcher{FieldOptions(1.0, -0.1)}, std::invalid_argument);
}

}  // namespace
}  // namespace scout::slam
