#include "scout/slam/relative_pose_cost.h"

#include <cmath>

namespace scout::slam {
namespace {

// Wraps an angle into [-pi, pi); the derivative of the wrap is 1.
double WrapAngle(double angle) {
  constexpr double kTwoPi = 2.0 * M_PI;
  return angle - kTwoPi * std::floor((angle + M_PI) / kTwoPi);
}

}  // namespace

RelativePoseCost::RelativePoseCost(const geometry::Rigid2d& measured, double translation_weight,
                                   double rotation_weight)
    : x_(measured.x()),
      y_(measured.y()),
      theta_(measured.theta()),
      translation_weight_(translation_weight),
      rotation_weight_(rotation_weight) {}

bool RelativePoseCost::Evaluate(double const* const* parameters, double* residuals,
                                double** jacobians) const {
  const double* first = parameters[0];
  const double* second = parameters[1];
  const double c = std::cos(first[2]);
  const double s = std::sin(first[2]);
  const double dx = second[0] - first[0];
  const double dy = second[1] - first[1];
  // 'second' in the frame of 'first'.
  const double along = c * dx + s * dy;
  const double across = -s * dx + c * dy;
  const double wt = translation_weight_;
  const double wr = rotation_weight_;
  residuals[0] = wt * (x_ - along);
  residuals[1] = wt * (y_ - across);
  residuals[2] = wr * WrapAngle(theta_ - (second[2] - first[2]));
  if (jacobians == nullptr) return true;
  // Row-major 3 x 3 blocks: d residual[row] / d parameter[column].
  if (jacobians[0] != nullptr) {
    double* j = jacobians[0];
    j[0] = wt * c, j[1] = wt * s, j[2] = -wt * across;
    j[3] = -wt * s, j[4] = wt * c, j[5] = wt * along;
    j[6] = 0.0, j[7] = 0.0, j[8] = wr;
  }
  if (jacobians[1] != nullptr) {
    double* j = jacobians[1];
    j[0] = -wt * c, j[1] = -wt * s, j[2] = 0.0;
    j[3] = wt * s, j[4] = -wt * c, j[5] = 0.0;
    j[6] = 0.0, j[7] = 0.0, j[8] = -wr;
  }
  return true;
}

}  // namespace scout::slam
