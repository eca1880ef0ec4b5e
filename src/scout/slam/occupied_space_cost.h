#ifndef SCOUT_SLAM_OCCUPIED_SPACE_COST_H_
#define SCOUT_SLAM_OCCUPIED_SPACE_COST_H_

#include <ceres/cost_function.h>
#include <ceres/cubic_interpolation.h>

#include <cmath>

#include "scout/grid/map_limits.h"
#include "scout/grid/probability_grid.h"
#include "scout/grid/probability_values.h"
#include "scout/slam/point_cloud.h"

namespace scout::slam {

// Presents the grid to ceres::BiCubicInterpolator as samples at cell centres
// (row = y, column = x). Every integer index is valid: the outside of the grid
// reads like unknown cells, so points may be interpolated anywhere.
class GridSamples {
 public:
  enum { DATA_DIMENSION = 1 };
  GridSamples(const grid::ProbabilityGrid& grid, double unknown_probability)
      : values_(grid.values().data()),
        width_(grid.limits().width()),
        height_(grid.limits().height()),
        unknown_probability_(unknown_probability) {}

  void GetValue(int row, int column, double* probability) const {
    if (static_cast<unsigned>(column) >= static_cast<unsigned>(width_) ||
        static_cast<unsigned>(row) >= static_cast<unsigned>(height_)) {
      *probability = unknown_probability_;
      return;
    }
    const uint16_t v = values_[static_cast<size_t>(row) * width_ + column] & grid::kMaxValue;
    *probability = v == grid::kUnknownValue ? unknown_probability_ : grid::ValueToProbability(v);
  }

 private:
  const uint16_t* values_;  // the grid's, row-major
  const int width_;
  const int height_;
  const double unknown_probability_;
};

// One residual per point, scale * (1 - v), with v the bicubic interpolation
// of 'Samples' (a ceres::BiCubicInterpolator source of values in [0, 1] at
// the cell centres of 'limits', higher on walls) at the point's position under
// the pose (x, y, theta). The Jacobian is written out from the interpolator's
// gradient: local SLAM matches every scan, and automatic differentiation
// through the bicubic spline took a third of the matcher's time.
template <typename Samples>
class InterpolatedPointCost : public ceres::CostFunction {
 public:
  // 'points' (scan frame) and 'samples' must outlive the cost.
  InterpolatedPointCost(double scale, const PointCloud& points, const grid::MapLimits& limits,
                        const Samples& samples)
      : scale_(scale), points_(points), limits_(limits), interpolator_(samples) {
    set_num_residuals(static_cast<int>(points.size()));
    mutable_parameter_block_sizes()->push_back(3);
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
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
      double value, d_row, d_column;
      interpolator_.Evaluate(row, column, &value, &d_row, &d_column);
      residuals[i] = scale_ * (1.0 - value);
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

 private:
  const double scale_;
  const PointCloud& points_;
  const grid::MapLimits limits_;
  const ceres::BiCubicInterpolator<Samples> interpolator_;
};

namespace internal {
// Holds the samples so they are built before the cost that reads them.
struct GridSamplesHolder {
  GridSamples samples;
};
}  // namespace internal

// The cost on the grid's probabilities: residual scale * (1 - p).
class OccupiedSpaceCost : private internal::GridSamplesHolder,
                          public InterpolatedPointCost<GridSamples> {
 public:
  // 'points' (scan frame) and 'grid' must outlive the cost; unknown cells and
  // the outside of the grid read as 'unknown_probability'.
  OccupiedSpaceCost(double scale, const PointCloud& points, const grid::ProbabilityGrid& grid,
                    double unknown_probability)
      : internal::GridSamplesHolder{GridSamples(grid, unknown_probability)},
        InterpolatedPointCost<GridSamples>(scale, points, grid.limits(), samples) {}
};

}  // namespace scout::slam

#endif  // SCOUT_SLAM_OCCUPIED_SPACE_COST_H_
