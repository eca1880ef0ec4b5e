#include "scout/geometry/rigid_transform.h"

#include <numbers>
#include <stdexcept>
#include <string>

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

Rigid2d FitRigid2d(const std::vector<Eigen::Vector2d>& from,
                   const std::vector<Eigen::Vector2d>& to) {
  if (from.size() != to.size()) {
    throw std::invalid_argument("FitRigid2d: " + std::to_string(from.size()) +
                                " points to fit onto " + std::to_string(to.size()));
  }
  if (from.empty()) return Rigid2d::Identity();
  Eigen::Vector2d mean_from = Eigen::Vector2d::Zero();
  Eigen::Vector2d mean_to = Eigen::Vector2d::Zero();
  for (size_t i = 0; i < from.size(); ++i) {
    mean_from += from[i];
    mean_to += to[i];
  }
  mean_from /= static_cast<double>(from.size());
  mean_to /= static_cast<double>(to.size());
  // The optimal angle maximises sum(to_c . R from_c), i.e. it is the angle of
  // (sum of dot products, sum of cross products) of the centred positions.
  double dot = 0.0;
  double cross = 0.0;
  for (size_t i = 0; i < from.size(); ++i) {
    const Eigen::Vector2d f = from[i] - mean_from;
    const Eigen::Vector2d t = to[i] - mean_to;
    dot += f.x() * t.x() + f.y() * t.y();
    cross += f.x() * t.y() - f.y() * t.x();
  }
  const double theta = (dot == 0.0 && cross == 0.0) ? 0.0 : std::atan2(cross, dot);
  const Rigid2d rotation(0.0, 0.0, theta);
  return Rigid2d(mean_to - rotation.Rotate(mean_from), theta);
}

}  // namespace scout::geometry
