#include "scout/explore/anchored_point.h"

#include <limits>

namespace scout::explore {

AnchoredPoint Anchor(const Eigen::Vector2d& global, const std::vector<SubmapPose>& submaps) {
  AnchoredPoint a;
  a.local = global;
  a.global_at_anchor = global;
  double best = std::numeric_limits<double>::infinity();
  for (const SubmapPose& s : submaps) {
    const double d2 = (s.global_pose.translation() - global).squaredNorm();
    if (d2 < best) {
      best = d2;
      a.submap_id = s.id;
      a.local = s.global_pose.inverse() * global;
    }
  }
  return a;
}

Eigen::Vector2d Resolve(const AnchoredPoint& point, const std::vector<SubmapPose>& submaps) {
  if (point.submap_id < 0) return point.local;
  for (const SubmapPose& s : submaps) {
    if (s.id == point.submap_id) return s.global_pose * point.local;
  }
  return point.global_at_anchor;
}

}  // namespace scout::explore
