#include "scout/io/scan_consistency.h"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace scout::io {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BgPoint = bg::model::point<double, 2, bg::cs::cartesian>;

}  // namespace

ScanConsistency MeasureScanConsistency(const std::vector<std::vector<Eigen::Vector2d>>& points,
                                       const std::vector<geometry::Rigid2d>& poses,
                                       const ScanConsistencyOptions& options) {
  if (points.size() != poses.size()) {
    throw std::invalid_argument("MeasureScanConsistency: " + std::to_string(points.size()) +
                                " scans but " + std::to_string(poses.size()) + " poses");
  }
  if (options.previous_scans < 1 || !(options.max_distance_m > 0.0)) {
    throw std::invalid_argument(
        "MeasureScanConsistency: previous_scans must be >= 1 and max_distance_m > 0");
  }
  const size_t window = static_cast<size_t>(options.previous_scans);
  const double max_distance_sq = options.max_distance_m * options.max_distance_m;
  // Each scan's returns in the world frame, placed once.
  std::vector<std::vector<BgPoint>> world(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    world[i].reserve(points[i].size());
    for (const Eigen::Vector2d& p : points[i]) {
      const Eigen::Vector2d w = poses[i] * p;
      world[i].emplace_back(w.x(), w.y());
    }
  }
  double sum_of_means = 0.0;
  ScanConsistency result;
  for (size_t i = window; i < world.size(); ++i) {
    std::vector<BgPoint> earlier;
    for (size_t k = i - window; k < i; ++k)
      earlier.insert(earlier.end(), world[k].begin(), world[k].end());
    if (earlier.empty()) continue;
    const bgi::rtree<BgPoint, bgi::rstar<16>> tree(earlier);  // packed: built in one go
    double sum = 0.0;
    int pairs = 0;
    for (const BgPoint& q : world[i]) {
      for (auto it = tree.qbegin(bgi::nearest(q, 1)); it != tree.qend(); ++it) {
        const double d_sq = bg::comparable_distance(q, *it);
        if (d_sq <= max_distance_sq) {
          sum += std::sqrt(d_sq);
          ++pairs;
        }
      }
    }
    if (pairs == 0) continue;
    sum_of_means += sum / pairs;
    ++result.scans;
  }
  result.mean_distance_m =
      result.scans > 0 ? sum_of_means / result.scans : std::numeric_limits<double>::quiet_NaN();
  return result;
}

}  // namespace scout::io
