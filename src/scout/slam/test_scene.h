#ifndef SCOUT_SLAM_TEST_SCENE_H_
#define SCOUT_SLAM_TEST_SCENE_H_

// Test-only: a room of line segments and an exact ray caster, so scan-matching
// tests know the true pose of every scan.

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "scout/geometry/rigid_transform.h"
#include "scout/grid/probability_grid.h"
#include "scout/grid/range_data_inserter.h"
#include "scout/sensor/laser_scan.h"
#include "scout/slam/point_cloud.h"

namespace scout::slam::testing {

struct Segment {
  Eigen::Vector2d a;
  Eigen::Vector2d b;
};

inline void AddBox(double x0, double y0, double x1, double y1, std::vector<Segment>* walls) {
  walls->push_back({{x0, y0}, {x1, y0}});
  walls->push_back({{x1, y0}, {x1, y1}});
  walls->push_back({{x1, y1}, {x0, y1}});
  walls->push_back({{x0, y1}, {x0, y0}});
}

// An asymmetric 10 m x 6 m room with a few obstacles, so a scan constrains all
// three pose parameters.
inline std::vector<Segment> Room() {
  std::vector<Segment> walls;
  AddBox(-5.0, -3.0, 5.0, 3.0, &walls);
  AddBox(1.0, 1.0, 1.6, 1.8, &walls);
  AddBox(-3.0, -2.2, -2.2, -1.5, &walls);
  walls.push_back({{-5.0, 0.5}, {-3.5, 2.0}});
  walls.push_back({{3.0, -3.0}, {4.0, -1.0}});
  // Slightly turned and shifted so walls do not run along cell borders, where
  // whether a return lands in one cell or its neighbour is a matter of rounding.
  const geometry::Rigid2d skew(0.013, 0.021, 0.03);
  for (Segment& s : walls) s = {skew * s.a, skew * s.b};
  return walls;
}

// Returns the distance along the ray to the nearest segment, +inf if none.
inline double CastRay(const std::vector<Segment>& walls, const Eigen::Vector2d& origin,
                      const Eigen::Vector2d& direction) {
  double best = std::numeric_limits<double>::infinity();
  for (const Segment& s : walls) {
    const Eigen::Vector2d e = s.b - s.a;
    const double denom = direction.x() * e.y() - direction.y() * e.x();
    if (std::abs(denom) < 1e-12) continue;
    const Eigen::Vector2d w = s.a - origin;
    const double t = (w.x() * e.y() - w.y() * e.x()) / denom;
    const double u = (w.x() * direction.y() - w.y() * direction.x()) / denom;
    if (t > 0.0 && u >= 0.0 && u <= 1.0) best = std::min(best, t);
  }
  return best;
}

// A 360-beam full-circle scan from 'pose' (no noise); beams beyond 'max_range_m'
// report +inf.
inline sensor::LaserScan CastScan(const std::vector<Segment>& walls, const geometry::Rigid2d& pose,
                                  double time_s = 0.0, int num_beams = 360,
                                  float max_range_m = 30.f) {
  sensor::LaserScan scan;
  scan.time_s = time_s;
  scan.angle_min_rad = -std::numbers::pi_v<float>;
  scan.angle_increment_rad = 2.f * std::numbers::pi_v<float> / static_cast<float>(num_beams);
  scan.range_min_m = 0.05f;
  scan.range_max_m = max_range_m;
  for (int k = 0; k < num_beams; ++k) {
    const double angle = pose.theta() + scan.angle_min_rad + k * scan.angle_increment_rad;
    const double range =
        CastRay(walls, pose.translation(), Eigen::Vector2d(std::cos(angle), std::sin(angle)));
    scan.ranges.push_back(range < max_range_m ? static_cast<float>(range)
                                              : std::numeric_limits<float>::infinity());
  }
  return scan;
}

// Returns the returns of a scan from 'pose', in the scan frame.
inline PointCloud ScanPoints(const std::vector<Segment>& walls, const geometry::Rigid2d& pose) {
  return sensor::ToRangeData(CastScan(walls, pose), {}).returns;
}

// A grid of the room built by inserting scans from a few known poses.
inline grid::ProbabilityGrid RoomGrid(double resolution_m = 0.05) {
  const std::vector<Segment> walls = Room();
  grid::ProbabilityGrid grid(grid::MapLimits(resolution_m, {-0.5, -0.5}, 20, 20));
  const grid::RangeDataInserter inserter({});
  for (int i = 0; i < 12; ++i) {
    const geometry::Rigid2d pose(-1.0 + 0.3 * (i % 4), -0.5 + 0.4 * (i / 4), 0.1 * i);
    const sensor::RangeData data = sensor::ToRangeData(CastScan(walls, pose), {});
    inserter.Insert(pose.translation(), TransformPointCloud(data.returns, pose),
                    TransformPointCloud(data.misses, pose), &grid);
  }
  return grid;
}

}  // namespace scout::slam::testing

#endif  // SCOUT_SLAM_TEST_SCENE_H_
