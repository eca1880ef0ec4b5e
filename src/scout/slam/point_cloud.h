#ifndef SCOUT_SLAM_POINT_CLOUD_H_
#define SCOUT_SLAM_POINT_CLOUD_H_

#include <Eigen/Core>
#include <vector>

#include "scout/geometry/rigid_transform.h"

namespace scout::slam {

// 2D points; the frame is given by context (scan/robot frame, submap frame...).
using PointCloud = std::vector<Eigen::Vector2d>;

// Returns 'points' transformed by 'pose'.
PointCloud TransformPointCloud(const PointCloud& points, const geometry::Rigid2d& pose);

// Returns one point per occupied voxel of edge 'voxel_size_m' (the first point
// that fell into it, so the result keeps the input order and stays a subset of
// real measurements). Throws std::invalid_argument unless voxel_size_m > 0.
PointCloud VoxelFilter(const PointCloud& points, double voxel_size_m);

struct AdaptiveVoxelFilterOptions {
  // Largest voxel edge tried; the filter never coarsens beyond it.
  double max_length_m = 0.5;
  // The filter picks the largest voxel that still leaves at least this many points.
  int min_num_points = 200;
  // Points farther than this from the scan origin are dropped first.
  double max_range_m = 50.0;
};

// Throws std::invalid_argument naming the first invalid option.
void Validate(const AdaptiveVoxelFilterOptions& options);

// Cartographer's adaptive voxel filter: drops points beyond max_range_m, then
// returns the result of the coarsest voxel filter (edge <= max_length_m) that
// keeps at least min_num_points points (all points if there are fewer).
// Throws std::invalid_argument on invalid options.
PointCloud AdaptiveVoxelFilter(const PointCloud& points, const AdaptiveVoxelFilterOptions& options);

// How the points' walls constrain a shift of the scan: (1 / N) times the sum
// of n n^T over the points whose neighbours within 'radius_m' (at least two
// besides the point) lie along a line, n that line's unit normal; the points
// elsewhere (corners, clutter, isolated returns) add nothing. Its eigenvalue
// along a direction is the fraction of the N points on walls across it: about
// 0 along a featureless corridor, whether or not its map ends in view.
// Throws std::invalid_argument unless radius_m > 0.
Eigen::Matrix2d WallNormalInformation(const PointCloud& points, double radius_m);

}  // namespace scout::slam

#endif  // SCOUT_SLAM_POINT_CLOUD_H_
