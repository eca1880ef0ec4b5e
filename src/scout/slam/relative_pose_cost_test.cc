#include "scout/slam/relative_pose_cost.h"

#include <ceres/autodiff_cost_function.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace scout::slam {
namespace {

// The residual of RelativePoseCost written as a template, for automatic
// differentiation: the reference its hand-written Jacobians must agree with.
struct AutoDiffRelativePose {
  template <typename T>
  bool operator()(const T* const first, const T* const second, T* residual) const {
    using std::cos, std::sin, std::floor;
    const T c = cos(first[2]);
    const T s = sin(first[2]);
    const T dx = second[0] - first[0];
    const T dy = second[1] - first[1];
    residual[0] = wt * (x - (c * dx + s * dy));
    residual[1] = wt * (y - (-s * dx + c * dy));
    const T angle = theta - (second[2] - first[2]);
    residual[2] = wr * (angle - 2.0 * M_PI * floor((angle + M_PI) / (2.0 * M_PI)));
    return true;
  }
  double x, y, theta, wt, wr;
};

TEST(RelativePoseCostTest, ResidualsAndJacobiansEqualAutomaticDifferentiation) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> position(-20.0, 20.0);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  for (int trial = 0; trial < 200; ++trial) {
    const geometry::Rigid2d measured(position(random), position(random), angle(random));
    const double wt = 1.0 + trial, wr = 3.0 + 2.0 * trial;
    const RelativePoseCost analytic(measured, wt, wr);
    const ceres::AutoDiffCostFunction<AutoDiffRelativePose, 3, 3, 3> automatic(
        new AutoDiffRelativePose{measured.x(), measured.y(), measured.theta(), wt, wr});
    const double first[3] = {position(random), position(random), angle(random)};
    const double second[3] = {position(random), position(random), angle(random)};
    const double* parameters[2] = {first, second};
    double r_analytic[3], r_automatic[3];
    double j_analytic[2][9], j_automatic[2][9];
    double* jacobians_analytic[2] = {j_analytic[0], j_analytic[1]};
    double* jacobians_automatic[2] = {j_automatic[0], j_automatic[1]};
    ASSERT_TRUE(analytic.Evaluate(parameters, r_analytic, jacobians_analytic));
    ASSERT_TRUE(automatic.Evaluate(parameters, r_automatic, jacobians_automatic));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(r_analytic[i], r_automatic[i], 1e-9 * wr) << trial;
    for (int b = 0; b < 2; ++b) {
      for (int i = 0; i < 9; ++i) {
        EXPECT_NEAR(j_analytic[b][i], j_automatic[b][i], 1e-9 * (1.0 + std::abs(j_automatic[b][i])))
            << "trial " << trial << " block " << b << " entry " << i;
      }
    }
    // Residuals alone, and one Jacobian block alone, are what Ceres asks for too.
    double r_only[3];
    ASSERT_TRUE(analytic.Evaluate(parameters, r_only, nullptr));
    double j_second[9];
    double* only_second[2] = {nullptr, j_second};
    ASSERT_TRUE(analytic.Evaluate(parameters, r_only, only_second));
    for (int i = 0; i < 9; ++i) EXPECT_EQ(j_second[i], j_analytic[1][i]);
  }
}

TEST(RelativePoseCostTest, ZeroWhereTheEstimatesAgreeWithTheMeasurement) {
  const geometry::Rigid2d first(1.0, -2.0, 3.0);
  const geometry::Rigid2d measured(0.5, 0.25, -3.0);  // a turn across +-pi
  const geometry::Rigid2d second = first * measured;
  const RelativePoseCost cost(measured, 10.0, 100.0);
  const double a[3] = {first.x(), first.y(), first.theta()};
  const double b[3] = {second.x(), second.y(), second.theta()};
  const double* parameters[2] = {a, b};
  double residuals[3];
  ASSERT_TRUE(cost.Evaluate(parameters, residuals, nullptr));
  for (double r : residuals) EXPECT_NEAR(r, 0.0, 1e-9);
}

}  // namespace
}  // namespace scout::slam
