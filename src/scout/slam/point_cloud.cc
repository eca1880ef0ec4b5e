#include "scout/slam/point_cloud.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_set>

namespace scout::slam {

PointCloud TransformPointCloud(const PointCloud& points, const geometry::Rigid2d& pose) {
  PointCloud result;
  result.reserve(points.size());
  for (const Eigen::Vector2d& p : points) result.push_back(pose * p);
  return result;
}

PointCloud VoxelFilter(const PointCloud& points, double voxel_size_m) {
  if (!(voxel_size_m > 0.0)) {
    throw std::invalid_argument("VoxelFilter: voxel_size_m must be > 0, got " +
                                std::to_string(voxel_size_m));
  }
  std::unordered_set<uint64_t> occupied;
  occupied.reserve(points.size());
  PointCloud result;
  for (const Eigen::Vector2d& p : points) {
    const auto vx = static_cast<int64_t>(std::floor(p.x() / voxel_size_m));
    const auto vy = static_cast<int64_t>(std::floor(p.y() / voxel_size_m));
    // 32 bits per axis cover any scan at any sensible voxel size.
    const uint64_t key =
        (static_cast<uint64_t>(static_cast<uint32_t>(vx)) << 32) | static_cast<uint32_t>(vy);
    if (occupied.insert(key).second) result.push_back(p);
  }
  return result;
}

void Validate(const AdaptiveVoxelFilterOptions& options) {
  if (!(options.max_length_m > 0.0)) {
    throw std::invalid_argument("adaptive_voxel_filter.max_length_m must be > 0, got " +
                                std::to_string(options.max_length_m));
  }
  if (options.min_num_points < 1) {
    throw std::invalid_argument("adaptive_voxel_filter.min_num_points must be >= 1, got " +
                                std::to_string(options.min_num_points));
  }
  if (!(options.max_range_m > 0.0)) {
    throw std::invalid_argument("adaptive_voxel_filter.max_range_m must be > 0, got " +
                                std::to_string(options.max_range_m));
  }
}

PointCloud AdaptiveVoxelFilter(const PointCloud& points,
                               const AdaptiveVoxelFilterOptions& options) {
  Validate(options);
  PointCloud in_range;
  in_range.reserve(points.size());
  for (const Eigen::Vector2d& p : points) {
    if (p.norm() <= options.max_range_m) in_range.push_back(p);
  }
  const auto enough = [&](const PointCloud& cloud) {
    return cloud.size() >= static_cast<size_t>(options.min_num_points);
  };
  if (!enough(in_range)) return in_range;
  PointCloud result = VoxelFilter(in_range, options.max_length_m);
  if (enough(result)) return result;
  // Halve the edge until enough points survive, then bisect between the last
  // edge that kept too few and the first that keeps enough (to ~10 %): a
  // coarser filter means cheaper matching, so the largest edge is wanted.
  for (double too_coarse = options.max_length_m; too_coarse > 1e-2 * options.max_length_m;
       too_coarse /= 2.0) {
    double fine_enough = too_coarse / 2.0;
    result = VoxelFilter(in_range, fine_enough);
    if (!enough(result)) continue;
    while (too_coarse / fine_enough > 1.1) {
      const double mid = 0.5 * (fine_enough + too_coarse);
      PointCloud candidate = VoxelFilter(in_range, mid);
      if (enough(candidate)) {
        fine_enough = mid;
        result = std::move(candidate);
      } else {
        too_coarse = mid;
      }
    }
    return result;
  }
  // Even the finest edge tried merges too much: keep every point.
  return in_range;
}

Eigen::Matrix2d WallNormalInformation(const PointCloud& points, double radius_m) {
  if (!(radius_m > 0.0)) {
    throw std::invalid_argument("WallNormalInformation: radius_m must be > 0");
  }
  Eigen::Matrix2d information = Eigen::Matrix2d::Zero();
  if (points.empty()) return information;
  const double radius_squared = radius_m * radius_m;
  for (const Eigen::Vector2d& point : points) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    Eigen::Matrix2d sum_outer = Eigen::Matrix2d::Zero();
    int count = 0;
    for (const Eigen::Vector2d& other : points) {
      if ((other - point).squaredNorm() > radius_squared) continue;
      sum += other;
      sum_outer += other * other.transpose();
      ++count;
    }
    if (count < 3) continue;
    const Eigen::Vector2d mean = sum / count;
    const Eigen::Matrix2d covariance = sum_outer / count - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(covariance);
    // Along a line the spread across it is noise; a fifth of the spread
    // along it (a standard deviation under half) still reads as a wall.
    if (eigen.eigenvalues()(0) > 0.2 * eigen.eigenvalues()(1)) continue;
    const Eigen::Vector2d normal = eigen.eigenvectors().col(0);
    information += normal * normal.transpose();
  }
  return information / static_cast<double>(points.size());
}

}  // namespace scout::slam
