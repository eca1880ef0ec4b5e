#include "scout/geometry/rigid_transform.h"

#include <numbers>

namespace scout::geometry {

double NormalizeAngle(double angle_rad) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double a = std::fmod(angle_rad + std::numbers::pi, kTwoPi);
  if (a < 0.0) a += kTwoPi;
  a -= std::numbers::pi;
  // fmod can return exactly 2*pi - pi = pi after rounding; keep the range half-open.
  return a >= std::numbers::pi ? a - kTwoPi : a;
}

std::ostream& operator<<(std::ostream& os, const Rigid2d& t) {
  return os << "{x: " << t.x() << ", y: " << t.y() << ", theta: " << t.theta() << "}";
}

double MaxDisplacementWithin(const Rigid2d& delta, const Eigen::Vector2d& center, double radius_m) {
  // A point q = center + r moves by (R - I) q + t = [(R - I) center + t] + (R - I) r, and
  // |(R - I) r| = 2 |sin(theta / 2)| |r|.
  const Eigen::Vector2d center_motion = delta * center - center;
  return center_motion.norm() + 2.0 * std::abs(std::sin(0.5 * delta.theta())) * radius_m;
}

}  // namespace scout::geometry
