#ifndef SCOUT_SLAM_OCCUPIED_SPACE_COST_H_
#define SCOUT_SLAM_OCCUPIED_SPACE_COST_H_

#include <ceres/cost_function.h>
#include <ceres/cubic_interpolation.h>

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

// One residual per point, scale * (1 - p), with p the bicubic interpolation
// of the grid at the point's position under the pose (x, y, theta). The
// Jacobian is written out from the interpolator's gradient: local SLAM matches
// every scan, and automatic differentiation through the bicubic spline took
// a third of the matcher's time.
class OccupiedSpaceCost : public ceres::CostFunction {
 public:
  // 'points' (scan frame) and 'grid' must outlive the cost; unknown cells and
  // the outside of the grid read as 'unknown_probability'.
  OccupiedSpaceCost(double scale, const PointCloud& points, const grid::ProbabilityGrid& grid,
                    double unknown_probability);

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override;

 private:
  const double scale_;
  const PointCloud& points_;
  const grid::MapLimits limits_;
  const GridSamples samples_;
  const ceres::BiCubicInterpolator<GridSamples> interpolator_;
};

}  // namespace scout::slam

#endif  // SCOUT_SLAM_OCCUPIED_SPACE_COST_H_
