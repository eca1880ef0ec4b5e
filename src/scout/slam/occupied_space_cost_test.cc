#include "scout/slam/occupied_space_cost.h"

#include <ceres/autodiff_cost_function.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scout/slam/test_scene.h"

namespace scout::slam {
namespace {

// The residuals of OccupiedSpaceCost through automatic differentiation of the
// same bicubic interpolation: the reference for its hand-written Jacobian.
class AutoDiffOccupiedSpace {
 public:
  AutoDiffOccupiedSpace(double scale, const PointCloud& points, const grid::ProbabilityGrid& grid)
      : scale_(scale),
        points_(points),
        limits_(grid.limits()),
        samples_(grid, 0.5),
        interpolator_(samples_) {}

  template <typename T>
  bool operator()(const T* const pose, T* residuals) const {
    using std::cos, std::sin;
    for (size_t i = 0; i < points_.size(); ++i) {
      const Eigen::Vector2d& p = points_[i];
      const T x = cos(pose[2]) * p.x() - sin(pose[2]) * p.y() + pose[0];
      const T y = sin(pose[2]) * p.x() + cos(pose[2]) * p.y() + pose[1];
      T probability;
      interpolator_.Evaluate((y - limits_.origin().y()) / limits_.resolution() - 0.5,
                             (x - limits_.origin().x()) / limits_.resolution() - 0.5, &probability);
      residuals[i] = scale_ * (1.0 - probability);
    }
    return true;
  }

 private:
  const double scale_;
  const PointCloud& points_;
  const grid::MapLimits limits_;
  const GridSamples samples_;
  const ceres::BiCubicInterpolator<GridSamples> interpolator_;
};

TEST(OccupiedSpaceCostTest, ResidualsAndJacobianEqualAutomaticDifferentiation) {
  const grid::ProbabilityGrid grid = testing::RoomGrid();
  const PointCloud points =
      testing::ScanPoints(testing::Room(), geometry::Rigid2d(0.3, -0.2, -0.4));
  const double scale = 1.0 / std::sqrt(static_cast<double>(points.size()));
  const OccupiedSpaceCost analytic(scale, points, grid, 0.5);
  const ceres::AutoDiffCostFunction<AutoDiffOccupiedSpace, ceres::DYNAMIC, 3> automatic(
      new AutoDiffOccupiedSpace(scale, points, grid), static_cast<int>(points.size()));
  ASSERT_EQ(analytic.num_residuals(), static_cast<int>(points.size()));
  std::mt19937 random(3);
  std::uniform_real_distribution<double> offset(-0.3, 0.3);
  const size_t n = points.size();
  for (int trial = 0; trial < 50; ++trial) {
    // Poses around the true one, and a few far off where points leave the grid.
    const double far = trial % 10 == 0 ? 8.0 : 0.0;
    const double pose[3] = {0.3 + offset(random) + far, -0.2 + offset(random),
                            -0.4 + offset(random)};
    const double* parameters[1] = {pose};
    std::vector<double> r_analytic(n), r_automatic(n), j_analytic(3 * n), j_automatic(3 * n);
    double* jacobian_analytic[1] = {j_analytic.data()};
    double* jacobian_automatic[1] = {j_automatic.data()};
    ASSERT_TRUE(analytic.Evaluate(parameters, r_analytic.data(), jacobian_analytic));
    ASSERT_TRUE(automatic.Evaluate(parameters, r_automatic.data(), jacobian_automatic));
    for (size_t i = 0; i < n; ++i) EXPECT_NEAR(r_analytic[i], r_automatic[i], 1e-12) << i;
    for (size_t i = 0; i < 3 * n; ++i) {
      EXPECT_NEAR(j_analytic[i], j_automatic[i], 1e-9 * (1.0 + std::abs(j_automatic[i])))
          << "trial " << trial << " point " << i / 3 << " parameter " << i % 3;
    }
    // Without a Jacobian requested, the same residuals.
    std::vector<double> r_only(n);
    ASSERT_TRUE(analytic.Evaluate(parameters, r_only.data(), nullptr));
    EXPECT_EQ(r_only, r_analytic);
  }
}

}  // namespace
}  // namespace scout::slam
