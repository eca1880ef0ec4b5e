#include "scout/explore/scan_memory.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "scout/common/format.h"

namespace scout::explore {

ScanMemory::ScanMemory(double memory_s, double radius_m)
    : memory_s_(memory_s), radius_m_(radius_m) {
  if (!(std::isfinite(memory_s) && memory_s >= 0.0) ||
      !(std::isfinite(radius_m) && radius_m >= 0.0)) {
    throw std::invalid_argument("ScanMemory: memory_s and radius_m must be finite and >= 0, got " +
                                FormatNumber(memory_s) + " and " + FormatNumber(radius_m));
  }
}

void ScanMemory::Add(double time_s, const geometry::Rigid2d& pose,
                     const std::vector<Eigen::Vector2d>& returns) {
  if (has_last_ && (pose.translation() - last_position_).norm() > kStillM) {
    moving_time_s_ += std::max(0.0, time_s - last_time_s_);
  }
  has_last_ = true;
  last_time_s_ = time_s;
  last_position_ = pose.translation();
  while (!scans_.empty() && (scans_.front().moving_time_s < moving_time_s_ - memory_s_ ||
                             static_cast<int>(scans_.size()) >= kMaxScans)) {
    scans_.pop_front();
  }
  if (memory_s_ <= 0.0) return;
  Scan scan{moving_time_s_, {}};
  for (const Eigen::Vector2d& p : returns) {
    if (p.norm() <= radius_m_) scan.points.push_back(pose * p);
  }
  scans_.push_back(std::move(scan));
}

std::vector<Eigen::Vector2d> ScanMemory::Around(const geometry::Rigid2d& pose) const {
  const geometry::Rigid2d from_memory = pose.inverse();
  std::vector<Eigen::Vector2d> out;
  for (const Scan& scan : scans_) {
    for (const Eigen::Vector2d& p : scan.points) {
      const Eigen::Vector2d q = from_memory * p;
      if (q.norm() <= radius_m_) out.push_back(q);
    }
  }
  return out;
}

}  // namespace scout::explore
