#include "scout/slam/occupied_space_cost.h"

#include <cmath>

#include "scout/grid/probability_values.h"

namespace scout::slam {

OccupiedSpaceCost::OccupiedSpaceCost(double scale, const PointCloud& points,
                                     const grid::ProbabilityGrid& grid, double unknown_probability)
    : scale_(scale),
      points_(points),
      limits_(grid.limits()),
      samples_(grid, unknown_probability),
      interpolator_(samples_) {
  set_num_residuals(static_cast<int>(points.size()));
  mutable_parameter_block_sizes()->push_back(3);
}

bool OccupiedSpaceCost::Evaluate(double const* const* parameters, double* residuals,
                                 double** jacobians) const {
  const double* pose = parameters[0];
  const double c = std::cos(pose[2]);
  const double s = std::sin(pose[2]);
  const double inv_resolution = 1.0 / limits_.resolution();
  double* jacobian = jacobians != nullptr ? jacobians[0] : nullptr;
  for (size_t i = 0; i < points_.size(); ++i) {
    const Eigen::Vector2d& p = points_[i];
    // The point rotated into the grid frame, then translated.
    const double rx = c * p.x() - s * p.y();
    const double ry = s * p.x() + c * p.y();
    // Sample (r, c) sits at the centre of cell (x = c, y = r).
    const double column = (rx + pose[0] - limits_.origin().x()) * inv_resolution - 0.5;
    const double row = (ry + pose[1] - limits_.origin().y()) * inv_resolution - 0.5;
    double probability, d_row, d_column;
    interpolator_.Evaluate(row, column, &probability, &d_row, &d_column);
    residuals[i] = scale_ * (1.0 - probability);
    if (jacobian != nullptr) {
      // d(column)/dx = d(row)/dy = 1 / resolution; d(rx, ry)/dtheta = (-ry, rx).
      const double dx = -scale_ * d_column * inv_resolution;
      const double dy = -scale_ * d_row * inv_resolution;
      jacobian[3 * i + 0] = dx;
      jacobian[3 * i + 1] = dy;
      jacobian[3 * i + 2] = -dx * ry + dy * rx;
    }
  }
  return true;
}

}  // namespace scout::slam
