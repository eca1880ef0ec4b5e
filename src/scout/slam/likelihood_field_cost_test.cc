#include "scout/slam/likelihood_field_cost.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "scout/slam/test_scene.h"

namespace scout::slam {
namespace {

using geometry::Rigid2d;

constexpr double kResolution = 0.05;
constexpr double kSigma = 0.06;

// A 40 x 40 grid of 5 cm cells with its origin at (0, 0): one wall cell
// (0.7) at (10, 10), a cell seen once as a wall and then missed once (0.54,
// still above 0.5) at (30, 30), free cells (0.45) along row 20 and the rest
// unknown.
grid::ProbabilityGrid HandBuiltGrid() {
  grid::ProbabilityGrid grid(grid::MapLimits(kResolution, {0.0, 0.0}, 40, 40));
  grid.SetProbability({10, 10}, 0.7f);
  grid.SetProbability({30, 30}, 0.54f);
  for (int x = 0; x < 40; ++x) grid.SetProbability({x, 20}, 0.45f);
  grid.FinishUpdate();
  return grid;
}

Eigen::Vector2d CellCentre(int x, int y) {
  return {(x + 0.5) * kResolution, (y + 0.5) * kResolution};
}

// The residual of one point at 'p' (grid frame, identity pose), scale 1.
double Residual(const LikelihoodField& field, const Eigen::Vector2d& p) {
  const PointCloud point = {p};
  const LikelihoodFieldCost cost(1.0, point, field);
  const double pose[3] = {0.0, 0.0, 0.0};
  const double* parameters[1] = {pose};
  double residual = 0.0;
  EXPECT_TRUE(cost.Evaluate(parameters, &residual, nullptr));
  return residual;
}

TEST(LikelihoodFieldTest, ScoresTheDistanceToTheNearestWallWhateverLiesBetween) {
  const grid::ProbabilityGrid grid = HandBuiltGrid();
  // The window around the whole grid.
  const PointCloud corners = {{0.0, 0.0}, {2.0, 2.0}};
  const LikelihoodField field(grid, Rigid2d(), corners, 0.5, {kSigma, 0.5});
  const auto expected = [](double distance_m) {
    return 1.0 - std::exp(-distance_m * distance_m / (2.0 * kSigma * kSigma));
  };
  // On a wall: no residual. The spline passes through the samples at cell centres.
  EXPECT_NEAR(Residual(field, CellCentre(10, 10)), 0.0, 1e-6);
  EXPECT_NEAR(Residual(field, CellCentre(30, 30)), 0.0, 1e-6);
  // Three cells from either wall, over unknown cells: the distance alone counts.
  EXPECT_NEAR(Residual(field, CellCentre(13, 10)), expected(3 * kResolution), 1e-6);
  EXPECT_NEAR(Residual(field, CellCentre(10, 13)), expected(3 * kResolution), 1e-6);
  EXPECT_NEAR(Residual(field, CellCentre(27, 30)), expected(3 * kResolution), 1e-6);
  // A free cell ten cells from the nearest wall: as far as unknown space.
  EXPECT_NEAR(Residual(field, CellCentre(10, 20)), expected(10 * kResolution), 1e-6);
  EXPECT_GT(Residual(field, CellCentre(10, 20)), 0.999);
  // A wide spread: distances beyond the tabulated ones (4096 cells²) alike.
  const double wide_sigma = 5.0;
  const LikelihoodField wide(grid, Rigid2d(), corners, 3.0, {wide_sigma, 0.5});
  const auto expected_wide = [&](double distance_m) {
    return 1.0 - std::exp(-distance_m * distance_m / (2.0 * wide_sigma * wide_sigma));
  };
  EXPECT_NEAR(Residual(wide, CellCentre(13, 10)), expected_wide(3 * kResolution), 1e-6);
  // 80 and 70 cells from the wall at (30, 30), inside the window: 11300 cells².
  EXPECT_NEAR(Residual(wide, CellCentre(-50, 100)), expected_wide(std::sqrt(11300.0) * kResolution),
              1e-6);
  // With walls only above 0.6, the cell at 0.54 is no wall.
  const LikelihoodField strict(grid, Rigid2d(), corners, 0.5, {kSigma, 0.6});
  EXPECT_GT(Residual(strict, CellCentre(30, 30)), 0.999);
  EXPECT_NEAR(Residual(strict, CellCentre(10, 10)), 0.0, 1e-6);
}

TEST(LikelihoodFieldTest, AGridWithoutWallsAndTheOutsideOfTheWindowScoreNothing) {
  grid::ProbabilityGrid grid(grid::MapLimits(kResolution, {0.0, 0.0}, 10, 10));
  grid.SetProbability({5, 5}, 0.45f);
  grid.FinishUpdate();
  const PointCloud points = {{0.2, 0.2}};
  const LikelihoodField field(grid, Rigid2d(), points, 0.2, {kSigma, 0.5});
  EXPECT_DOUBLE_EQ(Residual(field, {0.2, 0.2}), 1.0);
  // Outside the window: as far from walls as can be.
  EXPECT_DOUBLE_EQ(Residual(field, {-5.0, 3.0}), 1.0);
  // Without points there is no window.
  const LikelihoodField none(HandBuiltGrid(), Rigid2d(), {}, 0.5, {kSigma, 0.5});
  EXPECT_EQ(none.limits().num_cells(), 0);
  EXPECT_DOUBLE_EQ(Residual(none, CellCentre(10, 10)), 1.0);
}

TEST(LikelihoodFieldCostTest, JacobianEqualsCentralDifferences) {
  const grid::ProbabilityGrid grid = testing::RoomGrid();
  const Rigid2d truth(0.3, -0.2, -0.4);
  const PointCloud points = testing::ScanPoints(testing::Room(), truth);
  const LikelihoodField field(grid, truth, points, 1.0, {kSigma, 0.5});
  const double scale = 1.0 / std::sqrt(static_cast<double>(points.size()));
  const LikelihoodFieldCost cost(scale, points, field);
  ASSERT_EQ(cost.num_residuals(), static_cast<int>(points.size()));
  const size_t n = points.size();
  std::mt19937 random(5);
  std::uniform_real_distribution<double> offset(-0.08, 0.08);
  for (int trial = 0; trial < 20; ++trial) {
    const double pose[3] = {truth.x() + offset(random), truth.y() + offset(random),
                            truth.theta() + offset(random)};
    const double* parameters[1] = {pose};
    std::vector<double> residuals(n), jacobian(3 * n);
    double* jacobians[1] = {jacobian.data()};
    ASSERT_TRUE(cost.Evaluate(parameters, residuals.data(), jacobians));
    for (int k = 0; k < 3; ++k) {
      const double h = 1e-6;
      double plus[3] = {pose[0], pose[1], pose[2]}, minus[3] = {pose[0], pose[1], pose[2]};
      plus[k] += h;
      minus[k] -= h;
      std::vector<double> r_plus(n), r_minus(n);
      const double* p_plus[1] = {plus};
      const double* p_minus[1] = {minus};
      ASSERT_TRUE(cost.Evaluate(p_plus, r_plus.data(), nullptr));
      ASSERT_TRUE(cost.Evaluate(p_minus, r_minus.data(), nullptr));
      for (size_t i = 0; i < n; ++i) {
        const double numeric = (r_plus[i] - r_minus[i]) / (2.0 * h);
        EXPECT_NEAR(jacobian[3 * i + k], numeric, 1e-5 * (1.0 + std::abs(numeric)))
            << "trial " << trial << " point " << i << " parameter " << k;
      }
    }
  }
}

}  // namespace
}  // namespace scout::slam
