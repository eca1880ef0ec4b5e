#include "scout/synthetic/se2.h"

#include <cmath>

namespace scout::synthetic {
namespace {

// Below this rotation the series expansions of sin(t)/t and (1 - cos t)/t are used.
constexpr double kSmallAngleRad = 1e-6;

// Returns V(theta) * v, where V = [[a, -b], [b, a]], a = sin(t)/t, b = (1 - cos t)/t.
Eigen::Vector2d ApplyV(double theta, const Eigen::Vector2d& v) {
  double a = 1.0, b = 0.5 * theta;
  if (std::abs(theta) > kSmallAngleRad) {
    a = std::sin(theta) / theta;
    b = (1.0 - std::cos(theta)) / theta;
  }
  return {a * v.x() - b * v.y(), b * v.x() + a * v.y()};
}

// Returns V(theta)^-1 * t.
Eigen::Vector2d ApplyInverseV(double theta, const Eigen::Vector2d& t) {
  double a = 1.0, b = 0.5 * theta;
  if (std::abs(theta) > kSmallAngleRad) {
    a = std::sin(theta) / theta;
    b = (1.0 - std::cos(theta)) / theta;
  }
  const double det = a * a + b * b;
  return {(a * t.x() + b * t.y()) / det, (-b * t.x() + a * t.y()) / det};
}

}  // namespace

geometry::Rigid2d ScaleMotion(const geometry::Rigid2d& motion, double fraction) {
  const double theta = motion.theta();
  const Eigen::Vector2d v = ApplyInverseV(theta, motion.translation());
  const double scaled_theta = fraction * theta;
  return geometry::Rigid2d(ApplyV(scaled_theta, fraction * v), scaled_theta);
}

}  // namespace scout::synthetic
