#ifndef SCOUT_SLAM_GLOBAL_TEST_WORLD_H_
#define SCOUT_SLAM_GLOBAL_TEST_WORLD_H_

// Test-only: a corridor loop made of wall segments and a lidar over it, so
// global SLAM tests know the true pose of every scan. Not part of the library.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "scout/geometry/rigid_transform.h"
#include "scout/grid/probability_grid.h"
#include "scout/grid/range_data_inserter.h"
#include "scout/sensor/laser_scan.h"
#include "scout/slam/point_cloud.h"

namespace scout::slam::global_testing {

struct Wall {
  Eigen::Vector2d from;
  Eigen::Vector2d to;
};

inline void AddRectangle(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                         std::vector<Wall>* walls) {
  const Eigen::Vector2d a = lo, b(hi.x(), lo.y()), c = hi, d(lo.x(), hi.y());
  walls->insert(walls->end(), {{a, b}, {b, c}, {c, d}, {d, a}});
}

// A 3 m wide corridor around a 14 m x 6 m block (outer walls 20 m x 12 m,
// from (-10, -6) to (10, 6)). The corridor centre line is the rectangle
// (-8.5, -4.5) .. (8.5, 4.5). Both corridor walls carry boxes of random size
// at random spacing (fixed seed), at most 0.6 m deep: a bare corridor looks
// the same everywhere along its axis, and loop closures there would be
// guesses.
inline std::vector<Wall> CorridorLoop() {
  std::vector<Wall> walls;
  AddRectangle({-10.0, -6.0}, {10.0, 6.0}, &walls);
  AddRectangle({-7.0, -3.0}, {7.0, 3.0}, &walls);
  // Each corridor wall as (start, end, unit normal into the corridor).
  struct Side {
    Eigen::Vector2d from, to, inward;
  };
  const std::vector<Side> sides = {{{-10, -6}, {10, -6}, {0, 1}}, {{10, -6}, {10, 6}, {-1, 0}},
                                   {{10, 6}, {-10, 6}, {0, -1}},  {{-10, 6}, {-10, -6}, {1, 0}},
                                   {{-7, -3}, {7, -3}, {0, -1}},  {{7, -3}, {7, 3}, {1, 0}},
                                   {{7, 3}, {-7, 3}, {0, 1}},     {{-7, 3}, {-7, -3}, {-1, 0}}};
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> gap(1.2, 2.8), length(0.3, 1.0), depth(0.2, 0.6);
  for (const Side& side : sides) {
    const double wall_length = (side.to - side.from).norm();
    const Eigen::Vector2d along = (side.to - side.from) / wall_length;
    for (double t = gap(rng); t + 1.0 < wall_length; t += gap(rng)) {
      const double l = length(rng), d = depth(rng);
      const Eigen::Vector2d a = side.from + t * along;
      const Eigen::Vector2d b = a + l * along;
      const Eigen::Vector2d c = b + d * side.inward;
      const Eigen::Vector2d e = a + d * side.inward;
      walls.insert(walls.end(), {{a, b}, {b, c}, {c, e}, {e, a}});
      t += l;
    }
  }
  return walls;
}

// A pose on the corridor centre line (see CorridorLoop) at arc length 's',
// counter-clockwise from (-7.5, -4.5), with corners rounded to a 1 m radius
// so a differential drive could follow it. One lap is 44 + 2 pi metres.
inline geometry::Rigid2d RoundedLoopPose(double s) {
  constexpr double kRadius = 1.0;
  const double straight[4] = {17.0 - 2 * kRadius, 9.0 - 2 * kRadius, 17.0 - 2 * kRadius,
                              9.0 - 2 * kRadius};
  const Eigen::Vector2d corner_centres[4] = {{8.5 - kRadius, -4.5 + kRadius},
                                             {8.5 - kRadius, 4.5 - kRadius},
                                             {-8.5 + kRadius, 4.5 - kRadius},
                                             {-8.5 + kRadius, -4.5 + kRadius}};
  const double arc = 0.5 * M_PI * kRadius;
  const double lap = straight[0] + straight[1] + straight[2] + straight[3] + 4 * arc;
  s = std::fmod(s, lap);
  Eigen::Vector2d start(-8.5 + kRadius, -4.5);
  for (int side = 0; side < 4; ++side) {
    const double heading = side * 0.5 * M_PI;
    const Eigen::Vector2d dir(std::cos(heading), std::sin(heading));
    if (s < straight[side]) return geometry::Rigid2d(start + s * dir, heading);
    s -= straight[side];
    if (s < arc) {
      const double a = s / kRadius;  // angle turned along the corner
      const Eigen::Vector2d from_centre(std::sin(heading + a), -std::cos(heading + a));
      return geometry::Rigid2d(corner_centres[side] + kRadius * from_centre, heading + a);
    }
    s -= arc;
    start = corner_centres[side] + kRadius * Eigen::Vector2d(std::cos(heading), std::sin(heading));
  }
  return geometry::Rigid2d(start, 0.0);  // s == lap up to rounding
}

// Returns the range to the first wall hit along the ray, +infinity if none.
inline double CastRay(const std::vector<Wall>& walls, const Eigen::Vector2d& origin,
                      const Eigen::Vector2d& direction) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const Wall& w : walls) {
    const Eigen::Vector2d edge = w.to - w.from;
    const Eigen::Vector2d rel = w.from - origin;
    const double cross = direction.x() * edge.y() - direction.y() * edge.x();
    if (std::abs(cross) < 1e-12) continue;  // parallel
    const double t = (rel.x() * edge.y() - rel.y() * edge.x()) / cross;
    const double s = (rel.x() * direction.y() - rel.y() * direction.x()) / cross;
    if (t > 1e-9 && s >= 0.0 && s <= 1.0) nearest = std::min(nearest, t);
  }
  return nearest;
}

struct LidarModel {
  int num_beams = 360;
  double field_of_view_rad = 2.0 * M_PI;
  double max_range_m = 8.0;
  double range_noise_m = 0.0;  // standard deviation
};

// A scan from robot pose 'pose' (world frame); beyond max range reads +inf.
inline sensor::LaserScan SimulateScan(const std::vector<Wall>& walls, const geometry::Rigid2d& pose,
                                      double time_s, const LidarModel& lidar, std::mt19937* rng) {
  sensor::LaserScan scan;
  scan.time_s = time_s;
  scan.angle_min_rad = static_cast<float>(-0.5 * lidar.field_of_view_rad);
  scan.angle_increment_rad = static_cast<float>(lidar.field_of_view_rad / lidar.num_beams);
  scan.range_min_m = 0.1f;
  scan.range_max_m = static_cast<float>(lidar.max_range_m);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int k = 0; k < lidar.num_beams; ++k) {
    const double angle = pose.theta() + scan.angle_min_rad + k * scan.angle_increment_rad;
    double range =
        CastRay(walls, pose.translation(), Eigen::Vector2d(std::cos(angle), std::sin(angle)));
    if (lidar.range_noise_m > 0.0 && rng != nullptr) range += lidar.range_noise_m * noise(*rng);
    scan.ranges.push_back(range < lidar.max_range_m ? static_cast<float>(range)
                                                    : std::numeric_limits<float>::infinity());
  }
  return scan;
}

// Returns the returns of a noiseless scan from 'pose', in the robot frame.
inline PointCloud ScanReturns(const std::vector<Wall>& walls, const geometry::Rigid2d& pose) {
  return sensor::ToRangeData(SimulateScan(walls, pose, 0.0, {}, nullptr), {}).returns;
}

// A grid in the frame 'grid_frame' (world pose of the grid's frame) built
// from noiseless scans taken at 'world_poses'.
inline grid::ProbabilityGrid BuildGrid(const std::vector<Wall>& walls,
                                       const geometry::Rigid2d& grid_frame,
                                       const std::vector<geometry::Rigid2d>& world_poses) {
  grid::ProbabilityGrid grid(grid::MapLimits(0.05, {-1.0, -1.0}, 40, 40));
  const grid::RangeDataInserter inserter({});
  for (const geometry::Rigid2d& pose : world_poses) {
    const sensor::RangeData data =
        sensor::ToRangeData(SimulateScan(walls, pose, 0.0, {}, nullptr), {});
    const geometry::Rigid2d in_grid = grid_frame.inverse() * pose;
    inserter.Insert(in_grid.translation(), TransformPointCloud(data.returns, in_grid),
                    TransformPointCloud(data.misses, in_grid), &grid);
  }
  return grid;
}

}  // namespace scout::slam::global_testing

#endif  // SCOUT_SLAM_GLOBAL_TEST_WORLD_H_
