#include "scout/explore/trail.h"

#include <algorithm>

namespace scout::explore {

void Trail::Record(const Eigen::Vector2d& position, double max_length_m) {
  if (max_length_m <= 0.0) return Clear();
  if (!points_.empty() && (position - points_.back()).norm() < kStep_m) return;
  if (!points_.empty()) length_m_ += (position - points_.back()).norm();
  points_.push_back(position);
  while (points_.size() > 2 && length_m_ - (points_[1] - points_[0]).norm() >= max_length_m) {
    length_m_ -= (points_[1] - points_[0]).norm();
    points_.pop_front();
  }
}

void Trail::Clear() {
  points_.clear();
  length_m_ = 0.0;
}

std::vector<Eigen::Vector2d> Trail::Reversed(const Eigen::Vector2d& from) const {
  std::vector<Eigen::Vector2d> path{from};
  for (auto it = points_.rbegin(); it != points_.rend(); ++it) {
    if ((*it - path.back()).norm() >= kStep_m) path.push_back(*it);
  }
  return path;
}

std::vector<Eigen::Vector2d> WayBack(const std::vector<Eigen::Vector2d>& driven,
                                     const Eigen::Vector2d& from, double distance_m) {
  std::vector<Eigen::Vector2d> way{from};
  const double tolerance2 = kLoopTolerance_m * kLoopTolerance_m;
  for (auto it = driven.rbegin(); it != driven.rend(); ++it) {
    // The way stays short while loops are erased, so the search is cheap.
    const auto seen = std::find_if(way.begin(), way.end(), [&](const Eigen::Vector2d& p) {
      return (*it - p).squaredNorm() <= tolerance2;
    });
    if (seen != way.end()) {
      way.erase(seen + 1, way.end());
      continue;
    }
    way.push_back(*it);
    if ((*it - from).norm() >= distance_m) return way;
  }
  return {};
}

}  // namespace scout::explore
