#include "scout/synthetic/loop_closure_detector.h"

#include <cmath>
#include <stdexcept>

namespace scout::synthetic {

LoopClosureDetector::LoopClosureDetector(double radius_m, double sample_spacing_m)
    : radius_m_(radius_m), sample_spacing_m_(sample_spacing_m) {
  if (!(radius_m > 0.0) || !(sample_spacing_m >= 0.0)) {
    throw std::invalid_argument("LoopClosureDetector: radius must be > 0 and spacing >= 0");
  }
}

int64_t LoopClosureDetector::KeyOf(int64_t cell_x, int64_t cell_y) const {
  return static_cast<int64_t>((static_cast<uint64_t>(cell_x) << 32) ^
                              static_cast<uint32_t>(cell_y));
}

void LoopClosureDetector::Add(int submap_id, const Eigen::Vector2d& position) {
  if (submap_id >= static_cast<int>(last_kept_.size())) {
    last_kept_.resize(submap_id + 1);
    has_kept_.resize(submap_id + 1, false);
  }
  if (has_kept_[submap_id] && (position - last_kept_[submap_id]).norm() < sample_spacing_m_) {
    return;
  }
  has_kept_[submap_id] = true;
  last_kept_[submap_id] = position;
  const int64_t cx = static_cast<int64_t>(std::floor(position.x() / radius_m_));
  const int64_t cy = static_cast<int64_t>(std::floor(position.y() / radius_m_));
  buckets_[KeyOf(cx, cy)].push_back({position, submap_id});
}

int LoopClosureDetector::OldestNear(const Eigen::Vector2d& position, int max_id) const {
  const int64_t cx = static_cast<int64_t>(std::floor(position.x() / radius_m_));
  const int64_t cy = static_cast<int64_t>(std::floor(position.y() / radius_m_));
  int oldest = -1;
  for (int64_t dy = -1; dy <= 1; ++dy) {
    for (int64_t dx = -1; dx <= 1; ++dx) {
      const auto it = buckets_.find(KeyOf(cx + dx, cy + dy));
      if (it == buckets_.end()) continue;
      for (const Entry& entry : it->second) {
        if (entry.submap_id > max_id || (oldest >= 0 && entry.submap_id >= oldest)) continue;
        if ((entry.position - position).norm() <= radius_m_) oldest = entry.submap_id;
      }
    }
  }
  return oldest;
}

}  // namespace scout::synthetic
