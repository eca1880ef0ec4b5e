#ifndef SCOUT_GEOMETRY_BOX_H_
#define SCOUT_GEOMETRY_BOX_H_

#include <Eigen/Core>
#include <algorithm>
#include <limits>

#include "scout/geometry/rigid_transform.h"

namespace scout::geometry {

// An axis-aligned box [min, max] (closed). A default box is empty.
struct Box2d {
  Eigen::Vector2d min{std::numeric_limits<double>::infinity(),
                      std::numeric_limits<double>::infinity()};
  Eigen::Vector2d max{-std::numeric_limits<double>::infinity(),
                      -std::numeric_limits<double>::infinity()};

  Box2d() = default;
  Box2d(const Eigen::Vector2d& min_corner, const Eigen::Vector2d& max_corner)
      : min(min_corner), max(max_corner) {}

  bool empty() const { return min.x() > max.x() || min.y() > max.y(); }
  // Returns true if 'p' lies in the closed box.
  bool Contains(const Eigen::Vector2d& p) const {
    return p.x() >= min.x() && p.x() <= max.x() && p.y() >= min.y() && p.y() <= max.y();
  }
  // Returns true if the closed boxes share at least one point.
  bool Intersects(const Box2d& o) const {
    return !empty() && !o.empty() && min.x() <= o.max.x() && o.min.x() <= max.x() &&
           min.y() <= o.max.y() && o.min.y() <= max.y();
  }
  void Extend(const Eigen::Vector2d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  // Returns the box grown by 'margin_m' on every side.
  Box2d Inflated(double margin_m) const {
    return Box2d(min.array() - margin_m, max.array() + margin_m);
  }
  // Returns the Euclidean distance from 'p' to the box (0 inside).
  double DistanceTo(const Eigen::Vector2d& p) const {
    const double dx = std::max({min.x() - p.x(), 0.0, p.x() - max.x()});
    const double dy = std::max({min.y() - p.y(), 0.0, p.y() - max.y()});
    return std::hypot(dx, dy);
  }
  Eigen::Vector2d Center() const { return 0.5 * (min + max); }
  double Area() const { return empty() ? 0.0 : (max - min).prod(); }
};

// Returns the axis-aligned bounding box of 'box' after applying 'transform'.
Box2d TransformBox(const Rigid2d& transform, const Box2d& box);

}  // namespace scout::geometry

#endif  // SCOUT_GEOMETRY_BOX_H_
