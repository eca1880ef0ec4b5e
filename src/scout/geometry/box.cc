#include "scout/geometry/box.h"

namespace scout::geometry {

Box2d TransformBox(const Rigid2d& transform, const Box2d& box) {
  Box2d result;
  if (box.empty()) return result;
  result.Extend(transform * box.min);
  result.Extend(transform * box.max);
  result.Extend(transform * Eigen::Vector2d(box.min.x(), box.max.y()));
  result.Extend(transform * Eigen::Vector2d(box.max.x(), box.min.y()));
  return result;
}

}  // namespace scout::geometry
