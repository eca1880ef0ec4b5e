#ifndef SCOUT_GEOMETRY_SEGMENT_H_
#define SCOUT_GEOMETRY_SEGMENT_H_

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace scout::geometry {

// Squared distance from 'p' to the segment a-b (to 'a' when a == b).
inline double SquaredDistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                                       const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length_sq = ab.squaredNorm();
  const double t = length_sq > 0.0 ? std::clamp((p - a).dot(ab) / length_sq, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).squaredNorm();
}

inline double DistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                                const Eigen::Vector2d& b) {
  return std::sqrt(SquaredDistanceToSegment(p, a, b));
}

}  // namespace scout::geometry

#endif  // SCOUT_GEOMETRY_SEGMENT_H_
